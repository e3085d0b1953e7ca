package org.habla.recording;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.habla.net.Frame;

/**
 * Reads a recording record by record (see {@link Recorder} for the layout). A record is whole when its
 * header line ends with {@code \n}, is a JSON object, and the binary block it declares is all there. The
 * first record that is not whole ends the reading: {@link #next} returns null and {@link #cut} says where
 * and why, and whether it is a torn end — a daemon killed mid-write leaves a last record the file ends inside,
 * and every record before it reads back — or damage: a complete record that cannot be read, or a bad record
 * with whole records after it ({@link Cut}). Not thread-safe.
 */
public final class RecordingReader implements RecordingSource {

    /** The longest header line read (the config record is the largest). */
    public static final int MAX_LINE_BYTES = 16 << 20;
    /** The largest binary block read (an image or a chunk of audio). */
    public static final int MAX_BINARY_BYTES = 64 << 20;

    private static final ObjectMapper JSON = new ObjectMapper();

    private final InputStream in;
    private final Path file;
    private final long size;
    private final RecordingHeader header;
    private long offset;
    private long unknown;
    private Cut cut;
    private boolean ended;

    private RecordingReader(InputStream in, Path file, long size) throws IOException, RecordingException {
        this.in = in;
        this.file = file;
        this.size = size;
        Frame first = readFrame();
        if (first == null) {
            in.close();
            throw new RecordingException(cut == null ? "the file is empty, not a HABLA recording"
                    : "not a HABLA recording, or its header record is not whole: " + cut.reason());
        }
        try {
            this.header = RecordingCodec.header(first);
        } catch (RecordingException e) {
            in.close();
            throw e;
        }
    }

    /** Opens a recording and reads its header. */
    public static RecordingReader open(Path file) throws IOException, RecordingException {
        return new RecordingReader(new BufferedInputStream(Files.newInputStream(file), 65_536), file, Files.size(file));
    }

    /** Reads a whole recording into memory: its header, its events, and where it was cut, if it was. */
    public static Recording readAll(Path file) throws IOException, RecordingException {
        try (RecordingReader r = open(file)) {
            List<RecordedEvent> events = new ArrayList<>();
            for (RecordedEvent e = r.next(); e != null; e = r.next()) {
                events.add(e);
            }
            return new Recording(r.header(), events, r.cut());
        }
    }

    @Override
    public RecordingHeader header() {
        return header;
    }

    /** The next event, or null at the end of the whole records. */
    public RecordedEvent next() throws IOException {
        while (!ended) {
            long at = offset;
            Frame f = readFrame();
            if (f == null) {
                ended = true;
                return null;
            }
            try {
                RecordedEvent e = RecordingCodec.event(f);
                if (e != null) {
                    return e;
                }
                unknown++;
            } catch (RecordingException ex) {
                stop(at, ex.getMessage(), false);
            }
        }
        return null;
    }

    /** Where the readable part ended before the end of the file; empty if every byte was read. */
    public Optional<Cut> cut() {
        return Optional.ofNullable(cut);
    }

    /** Records of types this HABLA does not know, skipped. */
    public long unknownRecords() {
        return unknown;
    }

    /** The next whole frame, or null at the end of the file or at the first record that is not whole. */
    private Frame readFrame() throws IOException {
        long start = offset;
        ByteArrayOutputStream line = new ByteArrayOutputStream(256);
        while (true) {
            int c = in.read();
            if (c < 0) {
                if (line.size() > 0) {
                    return stop(start, "the header line has no end (" + line.size() + " bytes)", true);
                }
                return null;
            }
            offset++;
            if (c == '\n') {
                break;
            }
            if (line.size() >= MAX_LINE_BYTES) {
                return stop(start, "a header line is over " + MAX_LINE_BYTES + " bytes");
            }
            line.write(c);
        }
        ObjectNode header;
        try {
            JsonNode n = JSON.readTree(line.toByteArray());
            if (!(n instanceof ObjectNode o) || !o.path("type").isTextual()) {
                return stop(start, "a header line is not a JSON object with a \"type\"");
            }
            header = o;
        } catch (JsonProcessingException e) {
            return stop(start, "a header line is not JSON: " + e.getOriginalMessage());
        }
        JsonNode count = header.get("bytes");
        if (count == null) {
            return Frame.of(header);
        }
        if (!count.canConvertToInt() || count.intValue() < 0 || count.intValue() > MAX_BINARY_BYTES) {
            return stop(start, "a record declares \"bytes\": " + count + " (at most " + MAX_BINARY_BYTES + ")");
        }
        byte[] body = in.readNBytes(count.intValue());
        offset += body.length;
        if (body.length < count.intValue()) {
            return stop(start, "the binary block is short: " + body.length + " of " + count.intValue() + " bytes", true);
        }
        return new Frame(header, body);
    }

    private Frame stop(long start, String reason) throws IOException {
        return stop(start, reason, false);
    }

    /**
     * Ends the reading at the record at {@code start}. It is a torn end only when the file ends inside it and no
     * whole record follows; a complete record that is bad, or one with whole records after it, is damage.
     */
    private Frame stop(long start, String reason, boolean fileEndsInside) throws IOException {
        OptionalLong next = WholeRecordSearch.after(file, start, size, WholeRecordSearch.LINE_RECORD);
        cut = fileEndsInside && next.isEmpty() ? Cut.tornEnd(start, size - start, reason)
                : new Cut(start, size - start, reason, true, next);
        ended = true;
        return null;
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
