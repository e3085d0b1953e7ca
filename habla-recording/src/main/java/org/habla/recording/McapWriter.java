package org.habla.recording;

import com.github.luben.zstd.Zstd;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.zip.CRC32;

/**
 * Writes an MCAP file (format version 0), chunked, indexed and checksummed, in one pass:
 *
 * <pre>
 *   magic  Header  [Metadata]...  ( Chunk{Schema|Channel|Message...}  MessageIndex... )...  DataEnd(crc)
 *   summary: Schema... Channel... ChunkIndex... MetadataIndex... Statistics   SummaryOffset...   Footer(crc)  magic
 *   every record: opcode u8 | content length u64 LE | content;  strings: u32 LE length + UTF-8
 * </pre>
 *
 * Messages go into the current chunk; {@link #flushChunk} compresses it (zstd), writes it with the message
 * index of each of its channels, and hands the bytes to the stream. A file whose writer dies before
 * {@link #finish} ends after its last whole chunk, without a summary: readers that scan the data section read
 * every chunk written. Not thread-safe: one writer thread.
 */
final class McapWriter {

    static final byte[] MAGIC = {(byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
    static final int OP_HEADER = 0x01, OP_FOOTER = 0x02, OP_SCHEMA = 0x03, OP_CHANNEL = 0x04, OP_MESSAGE = 0x05,
            OP_CHUNK = 0x06, OP_MESSAGE_INDEX = 0x07, OP_CHUNK_INDEX = 0x08, OP_STATISTICS = 0x0B,
            OP_METADATA = 0x0C, OP_METADATA_INDEX = 0x0D, OP_SUMMARY_OFFSET = 0x0E, OP_DATA_END = 0x0F;
    /** The zstd level of the chunks: fast, and most of the JSON's redundancy. */
    static final int ZSTD_LEVEL = 3;
    /** A chunk is closed when its records reach this size, whatever the flush period. */
    static final int MAX_CHUNK_BYTES = 4 << 20;

    private final Out out;
    private final List<byte[]> schemaRecords = new ArrayList<>();
    private final List<byte[]> channelRecords = new ArrayList<>();
    private final List<byte[]> chunkIndexes = new ArrayList<>();
    private final List<byte[]> metadataIndexes = new ArrayList<>();
    private final Map<Integer, Long> messagesPerChannel = new TreeMap<>();
    private final ByteArrayOutputStream chunk = new ByteArrayOutputStream(1 << 16);
    private final Map<Integer, ByteArrayOutputStream> chunkIndex = new LinkedHashMap<>();
    private long chunkStart = Long.MAX_VALUE;
    private long chunkEnd;
    private long fileStart = Long.MAX_VALUE;
    private long fileEnd;
    private long messageCount;
    private int chunkCount;
    private int metadataCount;

    McapWriter(OutputStream stream, String profile, String library) throws IOException {
        this.out = new Out(stream);
        out.write(MAGIC);
        Rec h = new Rec().string(profile).string(library);
        out.write(h.record(OP_HEADER));
    }

    /** Adds a schema (inside the current chunk, and to the summary). */
    void schema(int id, String name, String encoding, byte[] data) {
        byte[] r = new Rec().u16(id).string(name).string(encoding).u32(data.length).bytes(data).record(OP_SCHEMA);
        schemaRecords.add(r);
        chunk.writeBytes(r);
    }

    /** Adds a channel (inside the current chunk, and to the summary). */
    void channel(int id, int schemaId, String topic, String messageEncoding, Map<String, String> metadata) {
        byte[] r = new Rec().u16(id).u16(schemaId).string(topic).string(messageEncoding).map(metadata)
                .record(OP_CHANNEL);
        channelRecords.add(r);
        chunk.writeBytes(r);
    }

    /** Adds a message to the current chunk. */
    void message(int channelId, long sequence, long logTimeNs, long publishTimeNs, byte[] data) throws IOException {
        long offsetInChunk = chunk.size();
        Rec m = new Rec().u16(channelId).u32((int) sequence).u64(logTimeNs).u64(publishTimeNs).bytes(data);
        chunk.writeBytes(m.record(OP_MESSAGE));
        Rec idx = new Rec().u64(logTimeNs).u64(offsetInChunk);
        chunkIndex.computeIfAbsent(channelId, c -> new ByteArrayOutputStream()).writeBytes(idx.content());
        chunkStart = Math.min(chunkStart, logTimeNs);
        chunkEnd = Math.max(chunkEnd, logTimeNs);
        fileStart = Math.min(fileStart, logTimeNs);
        fileEnd = Math.max(fileEnd, logTimeNs);
        messagesPerChannel.merge(channelId, 1L, Long::sum);
        messageCount++;
        if (chunk.size() >= MAX_CHUNK_BYTES) {
            flushChunk();
        }
    }

    /** A metadata record in the data section (the current chunk is closed first: metadata stays out of chunks). */
    void metadata(String name, Map<String, String> entries) throws IOException {
        flushChunk();
        long at = out.offset;
        byte[] r = new Rec().string(name).map(entries).record(OP_METADATA);
        out.write(r);
        metadataIndexes.add(new Rec().u64(at).u64(r.length).string(name).record(OP_METADATA_INDEX));
        metadataCount++;
    }

    /** Writes the current chunk and its message indexes, if it has anything, and flushes the stream. */
    void flushChunk() throws IOException {
        if (chunk.size() > 0) {
            byte[] records = chunk.toByteArray();
            CRC32 crc = new CRC32();
            crc.update(records);
            byte[] compressed = Zstd.compress(records, ZSTD_LEVEL);
            boolean messages = !chunkIndex.isEmpty();
            long start = out.offset;
            byte[] c = new Rec().u64(messages ? chunkStart : 0).u64(messages ? chunkEnd : 0).u64(records.length)
                    .u32((int) crc.getValue()).string("zstd").u64(compressed.length).bytes(compressed).record(OP_CHUNK);
            out.write(c);
            long indexStart = out.offset;
            Rec offsets = new Rec();
            for (Map.Entry<Integer, ByteArrayOutputStream> e : chunkIndex.entrySet()) {
                offsets.u16(e.getKey()).u64(out.offset);
                byte[] entries = e.getValue().toByteArray();
                out.write(new Rec().u16(e.getKey()).u32(entries.length).bytes(entries).record(OP_MESSAGE_INDEX));
            }
            long indexLength = out.offset - indexStart;
            byte[] offsetMap = offsets.content();
            chunkIndexes.add(new Rec().u64(messages ? chunkStart : 0).u64(messages ? chunkEnd : 0).u64(start)
                    .u64(c.length).u32(offsetMap.length).bytes(offsetMap).u64(indexLength).string("zstd")
                    .u64(compressed.length).u64(records.length).record(OP_CHUNK_INDEX));
            chunkCount++;
            chunk.reset();
            chunkIndex.clear();
            chunkStart = Long.MAX_VALUE;
            chunkEnd = 0;
        }
        out.stream.flush();
    }

    /** Closes the data section and writes the summary, the footer and the closing magic. */
    void finish() throws IOException {
        flushChunk();
        out.write(new Rec().u32((int) out.crc.getValue()).record(OP_DATA_END));
        long summaryStart = out.offset;
        out.crc.reset();
        List<byte[]> offsets = new ArrayList<>();
        group(OP_SCHEMA, schemaRecords, offsets);
        group(OP_CHANNEL, channelRecords, offsets);
        group(OP_CHUNK_INDEX, chunkIndexes, offsets);
        group(OP_METADATA_INDEX, metadataIndexes, offsets);
        Rec counts = new Rec();
        messagesPerChannel.forEach((id, n) -> counts.u16(id).u64(n));
        byte[] countMap = counts.content();
        byte[] stats = new Rec().u64(messageCount).u16(schemaRecords.size()).u32(channelRecords.size()).u32(0)
                .u32(metadataCount).u32(chunkCount).u64(messageCount == 0 ? 0 : fileStart).u64(fileEnd)
                .u32(countMap.length).bytes(countMap).record(OP_STATISTICS);
        group(OP_STATISTICS, List.of(stats), offsets);
        long summaryOffsetStart = out.offset;
        for (byte[] o : offsets) {
            out.write(o);
        }
        // The footer's CRC covers the summary and summary offsets and the footer up to the CRC itself.
        Rec footerHead = new Rec();
        footerHead.u8(OP_FOOTER).u64(20).u64(summaryStart).u64(summaryOffsetStart);
        out.crc.update(footerHead.content());
        long crc = out.crc.getValue();
        out.stream.write(footerHead.content());
        out.stream.write(new Rec().u32((int) crc).content());
        out.stream.write(MAGIC);
        out.stream.flush();
    }

    private void group(int opcode, List<byte[]> records, List<byte[]> offsets) throws IOException {
        if (records.isEmpty()) {
            return;
        }
        long start = out.offset;
        for (byte[] r : records) {
            out.write(r);
        }
        offsets.add(new Rec().u8(opcode).u64(start).u64(out.offset - start).record(OP_SUMMARY_OFFSET));
    }

    /** The stream with its byte count and a running CRC32 of what was written through {@link #write}. */
    private static final class Out {
        final OutputStream stream;
        final CRC32 crc = new CRC32();
        long offset;

        Out(OutputStream stream) {
            this.stream = stream;
        }

        void write(byte[] b) throws IOException {
            stream.write(b);
            crc.update(b);
            offset += b.length;
        }
    }

    /** One record's content, little-endian. */
    static final class Rec {
        private final ByteArrayOutputStream b = new ByteArrayOutputStream();

        Rec u8(int v) {
            b.write(v);
            return this;
        }

        Rec u16(int v) {
            b.write(v);
            b.write(v >>> 8);
            return this;
        }

        Rec u32(int v) {
            for (int i = 0; i < 4; i++) {
                b.write(v >>> (8 * i));
            }
            return this;
        }

        Rec u64(long v) {
            for (int i = 0; i < 8; i++) {
                b.write((int) (v >>> (8 * i)));
            }
            return this;
        }

        Rec bytes(byte[] d) {
            b.writeBytes(d);
            return this;
        }

        Rec string(String s) {
            byte[] d = s.getBytes(StandardCharsets.UTF_8);
            return u32(d.length).bytes(d);
        }

        Rec map(Map<String, String> m) {
            Rec inner = new Rec();
            m.forEach((k, v) -> inner.string(k).string(v));
            byte[] d = inner.content();
            return u32(d.length).bytes(d);
        }

        byte[] content() {
            return b.toByteArray();
        }

        byte[] record(int opcode) {
            byte[] c = content();
            return new Rec().u8(opcode).u64(c.length).bytes(c).content();
        }
    }
}
