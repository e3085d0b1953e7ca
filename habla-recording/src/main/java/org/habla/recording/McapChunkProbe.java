package org.habla.recording;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;

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

    /**
     * Opcode and length (9), then start, end, uncompressed size and CRC (28), then the compression's length (4):
     * the least a chunk record holds.
     */
    private static final int FIXED_HEAD = 9 + 28 + 4;

    private McapChunkProbe() {
    }

    @Override
    public byte firstByte() {
        return (byte) McapWriter.OP_CHUNK;
    }

    @Override
    public boolean wholeRecordAt(FileChannel ch, long at, long size) throws IOException {
        ByteBuffer head = WholeRecordSearch.read(ch, at, 9).order(ByteOrder.LITTLE_ENDIAN);
        if (head.remaining() < 9) {
            return false;
        }
        head.get();
        long length = head.getLong();
        if (length < FIXED_HEAD - 9 || length > McapRecordingReader.MAX_RECORD_BYTES || at + 9 + length > size) {
            return false;
        }
        ByteBuffer content = WholeRecordSearch.read(ch, at + 9, (int) length).order(ByteOrder.LITTLE_ENDIAN);
        if (content.remaining() < length) {
            return false;
        }
        try {
            McapChunk.records(content, at);
            return true;
        } catch (RecordingException | RuntimeException e) {
            return false;
        }
    }
}
