package org.habla.recording;

import com.github.luben.zstd.Zstd;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.util.zip.CRC32;

/**
 * A whole MCAP chunk record, for {@link WholeRecordSearch}: the Chunk opcode, a length that fits in the file, a
 * chunk header whose sizes agree with that length and whose compression is none or {@code zstd}, and records that
 * decompress to the declared size and match the chunk's CRC. Everything HABLA records lives in chunks, so a whole
 * chunk after a bad record means the file goes on past it.
 *
 * <pre>
 *   06 | length u64 | start u64 | end u64 | uncompressed size u64 | crc u32 | compression (u32 n, n bytes) | records (u64 n, n bytes)
 * </pre>
 */
final class McapChunkProbe implements WholeRecordSearch.Probe {

    static final McapChunkProbe INSTANCE = new McapChunkProbe();

    /** Opcode and length (9), then start, end, uncompressed size and CRC (28), then the compression's length (4). */
    private static final int FIXED_HEAD = 9 + 28 + 4;
    private static final String ZSTD = "zstd";

    private McapChunkProbe() {
    }

    @Override
    public byte firstByte() {
        return (byte) McapWriter.OP_CHUNK;
    }

    @Override
    public boolean wholeRecordAt(FileChannel ch, long at, long size) throws IOException {
        ByteBuffer head = WholeRecordSearch.read(ch, at, FIXED_HEAD + ZSTD.length() + 8).order(ByteOrder.LITTLE_ENDIAN);
        if (head.remaining() < FIXED_HEAD + 8) {
            return false;
        }
        head.get();
        long length = head.getLong();
        if (length < 0 || length > McapRecordingReader.MAX_RECORD_BYTES || at + 9 + length > size) {
            return false;
        }
        head.getLong();
        head.getLong();
        long uncompressed = head.getLong();
        long crc = Integer.toUnsignedLong(head.getInt());
        int compressionLength = head.getInt();
        if (compressionLength != 0 && compressionLength != ZSTD.length()
                || uncompressed < 0 || uncompressed > McapRecordingReader.MAX_RECORD_BYTES) {
            return false;
        }
        if (head.remaining() < compressionLength + 8) {
            return false;
        }
        byte[] compression = new byte[compressionLength];
        head.get(compression);
        if (compressionLength > 0 && !ZSTD.equals(new String(compression, StandardCharsets.US_ASCII))) {
            return false;
        }
        long recordsLength = head.getLong();
        if (recordsLength != length - (28 + 4 + compressionLength + 8)) {
            return false;
        }
        ByteBuffer stored = WholeRecordSearch.read(ch, at + FIXED_HEAD + compressionLength + 8, (int) recordsLength);
        if (stored.remaining() < recordsLength) {
            return false;
        }
        byte[] records = stored.array();
        if (compressionLength > 0) {
            try {
                records = Zstd.decompress(records, (int) uncompressed);
            } catch (RuntimeException e) {
                return false;
            }
        }
        if (records.length != uncompressed) {
            return false;
        }
        CRC32 c = new CRC32();
        c.update(records);
        return crc == 0 || c.getValue() == crc;
    }
}
