package org.habla.recording;

import com.github.luben.zstd.Zstd;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.zip.CRC32;

/**
 * The records inside an MCAP chunk record, checked: the chunk header's sizes agree with the record, the
 * compression is none or {@code zstd}, and the records decompress to the declared size and match the chunk's
 * CRC (when it gives one). One decoding for {@link McapRecordingReader}, which reads the records, and
 * {@link McapChunkProbe}, which only asks whether a chunk is whole.
 *
 * <pre>
 *   start u64 | end u64 | uncompressed size u64 | crc u32 | compression (u32 n, n bytes) | records (u64 n, n bytes)
 * </pre>
 */
final class McapChunk {

    private McapChunk() {
    }

    /**
     * The chunk's records, uncompressed, from {@code content} (the chunk record after its opcode and length,
     * read to its end); {@code at} is the record's place in the file, for the messages.
     */
    static byte[] records(ByteBuffer content, long at) throws RecordingException {
        try {
            content.getLong();
            content.getLong();
            long uncompressedSize = content.getLong();
            long crc = Integer.toUnsignedLong(content.getInt());
            int n = content.getInt();
            if (n < 0 || n > content.remaining()) {
                throw new RecordingException("the chunk at byte " + at + " names a compression of " + n + " bytes");
            }
            byte[] name = new byte[n];
            content.get(name);
            String compression = new String(name, StandardCharsets.UTF_8);
            long length = content.getLong();
            if (length != content.remaining() || uncompressedSize < 0
                    || uncompressedSize > McapRecordingReader.MAX_RECORD_BYTES) {
                throw new RecordingException("the chunk at byte " + at + " declares " + length
                        + " bytes of records, has " + content.remaining());
            }
            byte[] stored = new byte[(int) length];
            content.get(stored);
            byte[] records = switch (compression) {
                case "" -> stored;
                case "zstd" -> {
                    try {
                        yield Zstd.decompress(stored, (int) uncompressedSize);
                    } catch (RuntimeException e) {
                        throw new RecordingException("the chunk at byte " + at + " does not decompress: "
                                + e.getMessage());
                    }
                }
                default -> throw new RecordingException("the chunk at byte " + at + " is compressed with '"
                        + compression + "', which HABLA does not read");
            };
            if (records.length != uncompressedSize) {
                throw new RecordingException("the chunk at byte " + at + " holds " + records.length + " bytes, not "
                        + uncompressedSize);
            }
            if (crc != 0) {
                CRC32 c = new CRC32();
                c.update(records);
                if (c.getValue() != crc) {
                    throw new RecordingException("the chunk at byte " + at + " fails its CRC");
                }
            }
            return records;
        } catch (BufferUnderflowException e) {
            throw new RecordingException("the chunk at byte " + at + " ends inside its header");
        }
    }
}
