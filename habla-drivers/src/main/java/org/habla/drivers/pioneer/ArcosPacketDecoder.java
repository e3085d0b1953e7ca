package org.habla.drivers.pioneer;

/**
 * The resynchronising ARCOS receiver: bytes are pushed in as they arrive, in pieces of any size, and
 * whole packets with a good checksum come out.
 *
 * <p>It hunts for {@code 0xFA 0xFB}, reads the count, waits for the whole packet and checks the checksum.
 * A count outside {@value ArcosPacket#MIN_COUNT}..{@value ArcosPacket#MAX_COUNT} or a wrong checksum
 * drops only the {@code 0xFA} that started the bad packet and hunts again from the next byte, so a good
 * header hidden inside a corrupted packet is still found. Each bad packet and each run of garbage before
 * a header is reported once. The buffer is bounded; the decoder never blocks and never gives up.
 *
 * <p>Not thread-safe: one decoder per connection, used by the connection's reader.
 */
public final class ArcosPacketDecoder {

    /** What the decoder hands out. */
    public interface Listener {
        /** A packet with a good checksum. */
        void packet(ArcosPacket packet);

        /** Bytes that were dropped, and why. */
        void malformed(String what);
    }

    private static final int CAPACITY = 1024;

    private final byte[] buf = new byte[CAPACITY];
    private int start;
    private int end;
    /** Bytes skipped while hunting that are not yet reported. */
    private int skipped;
    /** Bytes still claimed by the last bad packet: skipping them is part of that packet's report. */
    private int shadow;
    private long packets;
    private long dropped;

    /** Pushes {@code length} bytes; calls {@code listener} for every packet they complete. */
    public void push(byte[] bytes, int offset, int length, Listener listener) {
        int at = offset;
        int left = length;
        while (left > 0) {
            if (end == CAPACITY) {
                compact();
            }
            int n = Math.min(left, CAPACITY - end);
            System.arraycopy(bytes, at, buf, end, n);
            end += n;
            at += n;
            left -= n;
            drain(listener);
        }
    }

    /** Pushes every byte of {@code bytes}. */
    public void push(byte[] bytes, Listener listener) {
        push(bytes, 0, bytes.length, listener);
    }

    /** Good packets handed out so far. */
    public long packets() {
        return packets;
    }

    /** Bad packets and garbage runs reported so far. */
    public long dropped() {
        return dropped;
    }

    /** Bytes held that do not yet form a whole packet. */
    public int pending() {
        return end - start;
    }

    private void drain(Listener listener) {
        while (true) {
            if (!huntHeader(listener)) {
                return;
            }
            if (end - start < 3) {
                return;
            }
            int count = buf[start + 2] & 0xFF;
            if (count < ArcosPacket.MIN_COUNT || count > ArcosPacket.MAX_COUNT) {
                // its length is unknown: it may claim as many bytes as the largest packet
                reject(listener, ArcosPacket.MAX_COUNT + 2, "ARCOS byte count " + count + " is outside " + ArcosPacket.MIN_COUNT + ".."
                        + ArcosPacket.MAX_COUNT);
                continue;
            }
            if (end - start < 3 + count) {
                return;
            }
            int dataLength = count - 2;
            int sent = ((buf[start + 3 + dataLength] & 0xFF) << 8) | (buf[start + 4 + dataLength] & 0xFF);
            int computed = ArcosPacket.checksum(buf, start + 3, dataLength);
            if (sent != computed) {
                reject(listener, 2 + count, String.format("ARCOS checksum 0x%04X does not match the computed 0x%04X (type 0x%02X, count %d)",
                        sent, computed, buf[start + 3] & 0xFF, count));
                continue;
            }
            byte[] data = new byte[dataLength];
            System.arraycopy(buf, start + 3, data, 0, dataLength);
            start += 3 + count;
            shadow = 0;
            packets++;
            listener.packet(ArcosPacket.wrap(data));
        }
    }

    /** Moves {@code start} to a 0xFA 0xFB pair; false if none is complete in the buffer yet. */
    private boolean huntHeader(Listener listener) {
        while (end - start >= 2) {
            if ((buf[start] & 0xFF) == ArcosPacket.HEADER_1 && (buf[start + 1] & 0xFF) == ArcosPacket.HEADER_2) {
                reportSkipped(listener);
                return true;
            }
            skip();
        }
        if (end - start == 1 && (buf[start] & 0xFF) != ArcosPacket.HEADER_1) {
            skip();
        }
        return false;
    }

    private void skip() {
        start++;
        if (shadow > 0) {
            shadow--;
        } else {
            skipped++;
        }
    }

    /** Drops the 0xFA at {@code start}; the {@code claimed} bytes after it are the bad packet's. */
    private void reject(Listener listener, int claimed, String why) {
        reportSkipped(listener);
        start++;
        shadow = claimed;
        dropped++;
        listener.malformed(why);
    }

    private void reportSkipped(Listener listener) {
        if (skipped > 0) {
            dropped++;
            listener.malformed(skipped + " byte(s) of garbage before an ARCOS header");
        }
        skipped = 0;
    }

    private void compact() {
        System.arraycopy(buf, start, buf, 0, end - start);
        end -= start;
        start = 0;
    }
}
