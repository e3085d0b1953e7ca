package org.habla.recording;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.Base64;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import org.habla.net.Frame;

/**
 * Reads an MCAP recording written by {@link McapEventFile} front to back, chunk by chunk, without its summary —
 * so a file cut by a kill (no summary, no footer, a torn last chunk) reads back every whole chunk. Each chunk's
 * CRC is checked; a chunk that fails it, or a record that is not whole, ends the reading and {@link #cut}
 * names its byte offset, what was wrong and whether it is a torn end or damage ({@link Cut}). Not thread-safe.
 */
public final class McapRecordingReader implements RecordingSource {

    /** The largest record read (a chunk holds at most {@link McapWriter#MAX_CHUNK_BYTES} plus one message). */
    public static final long MAX_RECORD_BYTES = 256L << 20;

    private static final ObjectMapper JSON = new ObjectMapper();

    private final InputStream in;
    private final Path file;
    private final long size;
    private final Map<Integer, String> topics = new HashMap<>();
    private final ArrayDeque<RecordedEvent> pending = new ArrayDeque<>();
    private RecordingHeader header;
    private long offset;
    private Cut cut;
    private boolean ended;

    private McapRecordingReader(InputStream in, Path file, long size) {
        this.in = in;
        this.file = file;
        this.size = size;
    }

    /** Whether the file starts with MCAP's magic bytes. */
    public static boolean isMcap(Path file) throws IOException {
        try (InputStream s = Files.newInputStream(file)) {
            return Arrays.equals(s.readNBytes(McapWriter.MAGIC.length), McapWriter.MAGIC);
        }
    }

    /** Opens an MCAP recording and reads up to its HABLA header (the {@code habla.recording} metadata). */
    public static McapRecordingReader open(Path file) throws IOException, RecordingException {
        McapRecordingReader r = new McapRecordingReader(new BufferedInputStream(Files.newInputStream(file), 1 << 16),
                file, Files.size(file));
        try {
            r.start();
        } catch (IOException | RecordingException e) {
            r.close();
            throw e;
        }
        return r;
    }

    private void start() throws IOException, RecordingException {
        byte[] magic = in.readNBytes(McapWriter.MAGIC.length);
        offset += magic.length;
        if (!Arrays.equals(magic, McapWriter.MAGIC)) {
            throw new RecordingException("not an MCAP file: it does not start with MCAP's magic bytes");
        }
        while (header == null) {
            long at = offset;
            Record r = readRecord();
            if (r == null) {
                throw new RecordingException("not a HABLA recording: no \"" + McapEventFile.METADATA_NAME
                        + "\" metadata" + (cut == null ? "" : " before the cut at byte " + cut.offset() + ": " + cut.reason()));
            }
            if (r.opcode == McapWriter.OP_METADATA) {
                ByteBuffer b = r.content();
                String name = string(b);
                if (name.equals(McapEventFile.METADATA_NAME)) {
                    Map<String, String> meta = map(b);
                    JsonNode h = JSON.readTree(meta.getOrDefault("header", "null"));
                    if (!(h instanceof ObjectNode o)) {
                        throw new RecordingException("the metadata at byte " + at + " has no HABLA header");
                    }
                    header = RecordingCodec.header(Frame.of(o));
                }
            } else if (r.opcode == McapWriter.OP_CHUNK || r.opcode == McapWriter.OP_MESSAGE) {
                throw new RecordingException("not a HABLA recording: messages come before the \""
                        + McapEventFile.METADATA_NAME + "\" metadata");
            }
        }
    }

    @Override
    public RecordingHeader header() {
        return header;
    }

    @Override
    public RecordedEvent next() throws IOException {
        while (pending.isEmpty() && !ended) {
            long at = offset;
            Record r = readRecord();
            if (r == null) {
                ended = true;
                break;
            }
            try {
                switch (r.opcode) {
                    case McapWriter.OP_CHUNK -> chunk(r.content(), at);
                    case McapWriter.OP_CHANNEL -> channel(r.content());
                    case McapWriter.OP_MESSAGE -> message(r.content(), at);
                    case McapWriter.OP_DATA_END -> ended = true;
                    default -> { }
                }
            } catch (RecordingException | RuntimeException e) {
                stop(at, "damaged: " + e.getMessage());
            }
        }
        return pending.poll();
    }

    @Override
    public Optional<Cut> cut() {
        return Optional.ofNullable(cut);
    }

    private void chunk(ByteBuffer b, long at) throws RecordingException {
        byte[] records = McapChunk.records(b, at);
        ByteBuffer inner = ByteBuffer.wrap(records).order(ByteOrder.LITTLE_ENDIAN);
        while (inner.hasRemaining()) {
            int op = inner.get() & 0xff;
            long len = inner.getLong();
            if (len > inner.remaining()) {
                throw new RecordingException("a record in the chunk at byte " + at + " runs past the chunk");
            }
            ByteBuffer content = inner.slice(inner.position(), (int) len).order(ByteOrder.LITTLE_ENDIAN);
            inner.position(inner.position() + (int) len);
            switch (op) {
                case McapWriter.OP_CHANNEL -> channel(content);
                case McapWriter.OP_MESSAGE -> message(content, at);
                default -> { }
            }
        }
    }

    private void channel(ByteBuffer b) {
        int id = Short.toUnsignedInt(b.getShort());
        b.getShort();
        topics.put(id, string(b));
    }

    private void message(ByteBuffer b, long at) throws RecordingException {
        int channel = Short.toUnsignedInt(b.getShort());
        b.getInt();
        b.getLong();
        b.getLong();
        if (!topics.containsKey(channel)) {
            throw new RecordingException("a message near byte " + at + " is on channel " + channel
                    + ", which no channel record announced");
        }
        byte[] data = new byte[b.remaining()];
        b.get(data);
        JsonNode n;
        try {
            n = JSON.readTree(data);
        } catch (IOException e) {
            throw new RecordingException("a message near byte " + at + " is not JSON");
        }
        if (!(n instanceof ObjectNode m)) {
            throw new RecordingException("a message near byte " + at + " is not a JSON object");
        }
        byte[] body = null;
        if (m.has("data")) {
            body = Base64.getDecoder().decode(m.remove("data").asText());
            for (String f : new String[] {"timestamp", "frame_id", "format"}) {
                m.remove(f);
            }
        }
        RecordedEvent e = RecordingCodec.event(body == null ? Frame.of(m) : new Frame(m, body));
        if (e != null) {
            pending.add(e);
        }
    }

    /** The next whole record, or null at the end of the file or at the first record that is not whole. */
    private Record readRecord() throws IOException {
        long start = offset;
        int op = in.read();
        if (op < 0) {
            return null;
        }
        byte[] len = in.readNBytes(8);
        if (len.length < 8) {
            return stop(start, "the record at the end has no whole length", true);
        }
        long length = ByteBuffer.wrap(len).order(ByteOrder.LITTLE_ENDIAN).getLong();
        if (op == McapWriter.OP_FOOTER) {
            ended = true;
            return null;
        }
        if (length < 0 || length > MAX_RECORD_BYTES) {
            return stop(start, "a record declares " + Long.toUnsignedString(length) + " bytes (at most "
                    + MAX_RECORD_BYTES + ")");
        }
        byte[] content = in.readNBytes((int) length);
        offset += 9 + content.length;
        if (content.length < length) {
            return stop(start, "the last record is short: " + content.length + " of " + length + " bytes", true);
        }
        return new Record(op, content);
    }

    private Record stop(long start, String reason) throws IOException {
        return stop(start, reason, false);
    }

    /**
     * Ends the reading at the record at {@code start}: a torn end only when the file ends inside it and no whole
     * chunk follows; a complete record that is bad (a failed CRC, a size no writer writes), or one with whole
     * chunks after it, is damage.
     */
    private Record stop(long start, String reason, boolean fileEndsInside) throws IOException {
        java.util.OptionalLong next = WholeRecordSearch.after(file, start, size, McapChunkProbe.INSTANCE);
        cut = fileEndsInside && next.isEmpty() ? Cut.tornEnd(start, size - start, reason)
                : new Cut(start, size - start, reason, true, next);
        ended = true;
        return null;
    }

    private record Record(int opcode, byte[] bytes) {
        ByteBuffer content() {
            return ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
        }
    }

    private static String string(ByteBuffer b) {
        int n = b.getInt();
        if (n < 0 || n > b.remaining()) {
            throw new IllegalArgumentException("a string of " + n + " bytes runs past its record");
        }
        byte[] s = new byte[n];
        b.get(s);
        return new String(s, StandardCharsets.UTF_8);
    }

    private static Map<String, String> map(ByteBuffer b) {
        int n = b.getInt();
        ByteBuffer m = b.slice(b.position(), n).order(ByteOrder.LITTLE_ENDIAN);
        b.position(b.position() + n);
        Map<String, String> out = new LinkedHashMap<>();
        while (m.hasRemaining()) {
            out.put(string(m), string(m));
        }
        return out;
    }

    @Override
    public void close() throws IOException {
        in.close();
    }

}
