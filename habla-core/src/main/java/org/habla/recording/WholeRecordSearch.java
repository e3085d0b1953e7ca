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
 * Looks past a record that could not be read for the next whole one, to tell damage from a torn end. A whole
 * record starts with the bytes {@code {"type":"} (as a recorder writes every record, {@code type} first), its
 * line is a JSON object with a numeric {@code "t"}, ends with {@code \n}, and the binary block it declares fits
 * in the file. A record may start anywhere (right after another's binary block, not only after a newline), so
 * every {@code {} is a candidate; the prefix rules out nearly all of them at once. One pass from the bad record
 * to the end of the file, in blocks of {@value #BLOCK_BYTES} bytes.
 */
final class WholeRecordSearch {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final byte[] PREFIX = "{\"type\":\"".getBytes(StandardCharsets.US_ASCII);
    private static final int BLOCK_BYTES = 65_536;

    private WholeRecordSearch() {
    }

    /** The offset of the first whole record that starts after {@code from}, if any. */
    static OptionalLong after(Path file, long from, long size) throws IOException {
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
            ByteBuffer block = ByteBuffer.allocate(BLOCK_BYTES);
            for (long base = from + 1; base < size; ) {
                block.clear();
                int n = ch.read(block, base);
                if (n <= 0) {
                    break;
                }
                for (int i = 0; i < n; i++) {
                    if (block.get(i) == '{' && startsWholeRecord(ch, base + i, size)) {
                        return OptionalLong.of(base + i);
                    }
                }
                base += n;
            }
        }
        return OptionalLong.empty();
    }

    private static boolean startsWholeRecord(FileChannel ch, long at, long size) throws IOException {
        ByteBuffer prefix = ByteBuffer.allocate(PREFIX.length);
        while (prefix.hasRemaining() && ch.read(prefix, at + prefix.position()) > 0) {
            // fill the prefix
        }
        if (prefix.hasRemaining() || !java.util.Arrays.equals(prefix.array(), PREFIX)) {
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
