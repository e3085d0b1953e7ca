package org.habla.recording;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.habla.net.Frame;
import org.habla.net.FrameException;
import org.habla.net.FrameReader;

/**
 * Reads a recording record by record (see {@link Recorder} for the layout). A record is whole when its
 * header line ends with {@code \n}, is a JSON object, and the binary block it declares is all there. The
 * first record that is not whole ends the reading: {@link #next} returns null and {@link #cut} says where
 * and why, and whether it is a torn end — a daemon killed mid-write leaves a last record the file ends inside,
 * and every record before it reads back — or damage: a complete record that cannot be read, or a bad record
 * with whole records after it ({@link Cut}). Records are read by the {@link FrameReader} every HABLA socket reads
 * its frames with, within {@link #MAX_LINE_BYTES} and {@link #MAX_BINARY_BYTES}. Not thread-safe.
 */
public final class RecordingReader implements RecordingSource {

    /** The longest header line read (the config record is the largest). */
    public static final int MAX_LINE_BYTES = 16 << 20;
    /** The largest binary block read (an image or a chunk of audio). */
    public static final int MAX_BINARY_BYTES = 64 << 20;

    /** How much of the file each read asks for. */
    private static final int READ_BYTES = 65_536;

    private final InputStream in;
    private final FrameReader frames;
    private final Path file;
    private final long size;
    private final RecordingHeader header;
    private long unknown;
    private Cut cut;
    private boolean ended;

    private RecordingReader(InputStream in, Path file, long size) throws IOException, RecordingException {
        this.in = in;
        this.frames = new FrameReader(in, MAX_LINE_BYTES, MAX_BINARY_BYTES);
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
        return new RecordingReader(new BufferedInputStream(Files.newInputStream(file), READ_BYTES), file,
                Files.size(file));
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
            long at = frames.position();
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
        long start = frames.position();
        Frame f;
        try {
            f = frames.read();
        } catch (FrameException e) {
            // "truncated": the file ends inside the record's line or block (a torn end, if nothing whole follows).
            return stop(start, "record at byte " + start + ": " + e.getMessage(), e.code().equals("truncated"));
        }
        if (f != null && !f.header().path("type").isTextual()) {
            return stop(start, "record at byte " + start + ": a header line is not a JSON object with a \"type\"");
        }
        return f;
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
