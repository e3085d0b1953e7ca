package org.habla.recording;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.OptionalLong;

/**
 * Looks past a record that could not be read for the next whole one, to tell damage from a torn end: a kill leaves
 * nothing whole after the record it tore. A record may start anywhere after the bad one (right after another's
 * binary block, inside what a corrupted length swallowed), so every byte that can begin a record of the format is a
 * candidate, and the format's {@link Probe} rules nearly all of them out from their first bytes. One pass from the
 * bad record to the end of the file, in blocks of {@value #BLOCK_BYTES} bytes.
 */
final class WholeRecordSearch {

    /** How a format's whole record looks from its first byte on. */
    interface Probe {
        /** The byte every record of the format begins with. */
        byte firstByte();

        /** Whether a whole record starts at {@code at} of a file of {@code size} bytes. */
        boolean wholeRecordAt(FileChannel ch, long at, long size) throws IOException;
    }

    /**
     * The line format's records: they begin with {@code {"type":"} (a recorder writes {@code type} first), the line
     * is a JSON object with a numeric {@code "t"} ended by {@code \n}, and the binary block it declares fits.
     */
    static final Probe LINE_RECORD = new Probe() {
        @Override
        public byte firstByte() {
            return '{';
        }

        @Override
        public boolean wholeRecordAt(FileChannel ch, long at, long size) throws IOException {
            return startsWholeLine(ch, at, size);
        }
    };

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final byte[] PREFIX = "{\"type\":\"".getBytes(StandardCharsets.US_ASCII);
    private static final int BLOCK_BYTES = 65_536;

    private WholeRecordSearch() {
    }

    /** The offset of the first whole record that starts after {@code from}, if any. */
    static OptionalLong after(Path file, long from, long size, Probe probe) throws IOException {
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
            ByteBuffer block = ByteBuffer.allocate(BLOCK_BYTES);
            byte first = probe.firstByte();
            for (long base = from + 1; base < size; ) {
                block.clear();
                int n = ch.read(block, base);
                if (n <= 0) {
                    break;
                }
                for (int i = 0; i < n; i++) {
                    if (block.get(i) == first && probe.wholeRecordAt(ch, base + i, size)) {
                        return OptionalLong.of(base + i);
                    }
                }
                base += n;
            }
        }
        return OptionalLong.empty();
    }

    /** Reads exactly {@code n} bytes at {@code at}, or fewer at the end of the file. */
    static ByteBuffer read(FileChannel ch, long at, int n) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(n);
        while (b.hasRemaining() && ch.read(b, at + b.position()) > 0) {
            // fill
        }
        return b.flip();
    }

    private static boolean startsWholeLine(FileChannel ch, long at, long size) throws IOException {
        ByteBuffer prefix = read(ch, at, PREFIX.length);
        if (prefix.remaining() < PREFIX.length || !java.util.Arrays.equals(prefix.array(), PREFIX)) {
            return false;
        }
        ByteArrayOutputStream line = new ByteArrayOutputStream(256);
        ByteBuffer chunk = ByteBuffer.allocate(4_096);
        for (long pos = at; line.size() < RecordingReader.MAX_LINE_BYTES; ) {
            chunk.clear();
            int n = ch.read(chunk, pos);
            if (n <= 0) {
                return false;
            }
            for (int i = 0; i < n; i++) {
                if (chunk.get(i) == '\n') {
                    line.write(chunk.array(), 0, i);
                    return header(line.toByteArray(), pos + i + 1, size);
                }
            }
            line.write(chunk.array(), 0, n);
            pos += n;
        }
        return false;
    }

    /** Whether {@code line} is a record header whose block, starting at {@code bodyAt}, fits in the file. */
    private static boolean header(byte[] line, long bodyAt, long size) {
        JsonNode n;
        try {
            n = JSON.readTree(line);
        } catch (IOException e) {
            return false;
        }
        if (n == null || !n.isObject() || !n.path("type").isTextual() || !n.path("t").isNumber()) {
            return false;
        }
        JsonNode bytes = n.get("bytes");
        if (bytes == null) {
            return true;
        }
        return bytes.canConvertToInt() && bytes.intValue() >= 0 && bytes.intValue() <= RecordingReader.MAX_BINARY_BYTES
                && bodyAt + bytes.intValue() <= size;
    }
}
