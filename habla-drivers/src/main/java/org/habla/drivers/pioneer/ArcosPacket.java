package org.habla.drivers.pioneer;

import java.util.Arrays;
import java.util.HexFormat;

/**
 * One ARCOS packet: its data bytes (the command number or packet type, then the arguments or fields),
 * without the framing. Framing is the same in both directions:
 *
 * <pre>
 *  +------+------+-------+---------------------------+----------+----------+
 *  | 0xFA | 0xFB | count | data: type, fields (N)    | sum high | sum low  |
 *  +------+------+-------+---------------------------+----------+----------+
 *                  count = N + 2 (the data and the checksum, not the header or the count byte)
 * </pre>
 *
 * The checksum is the only big-endian item of the protocol; every integer inside the data is
 * little-endian.
 */
public final class ArcosPacket {

    /** The first header byte. */
    public static final int HEADER_1 = 0xFA;
    /** The second header byte. */
    public static final int HEADER_2 = 0xFB;
    /**
     * The largest count byte this side sends or accepts. P2OS ignores larger packets and no firmware or
     * simulator in the reference sends one, so a larger count is taken as corruption.
     */
    public static final int MAX_COUNT = 200;
    /** The smallest count byte: a type byte and the two checksum bytes. */
    public static final int MIN_COUNT = 3;

    private final byte[] data;

    private ArcosPacket(byte[] data) {
        if (data.length < 1 || data.length > MAX_COUNT - 2) {
            throw new IllegalArgumentException("an ARCOS packet carries 1.." + (MAX_COUNT - 2)
                    + " data bytes, not " + data.length);
        }
        this.data = data;
    }

    /** A packet holding a copy of {@code data} (type byte first). */
    public static ArcosPacket of(byte... data) {
        return new ArcosPacket(data.clone());
    }

    static ArcosPacket wrap(byte[] data) {
        return new ArcosPacket(data);
    }

    /** The command number (client to robot) or packet type (robot to client), 0..255. */
    public int type() {
        return data[0] & 0xFF;
    }

    /** Bytes after the type byte. */
    public int payloadLength() {
        return data.length - 1;
    }

    /** A copy of the bytes after the type byte. */
    public byte[] payload() {
        return Arrays.copyOfRange(data, 1, data.length);
    }

    /** A copy of the data bytes, type byte first. */
    public byte[] data() {
        return data.clone();
    }

    /** The packet as it travels: header, count, data, checksum. */
    public byte[] toWire() {
        byte[] wire = new byte[data.length + 5];
        wire[0] = (byte) HEADER_1;
        wire[1] = (byte) HEADER_2;
        wire[2] = (byte) (data.length + 2);
        System.arraycopy(data, 0, wire, 3, data.length);
        int sum = checksum(data, 0, data.length);
        wire[wire.length - 2] = (byte) (sum >>> 8);
        wire[wire.length - 1] = (byte) sum;
        return wire;
    }

    /**
     * The ARCOS checksum of {@code length} data bytes: the bytes taken in pairs as 16-bit words (first byte
     * high) summed modulo 2^16, an odd last byte XORed into the low byte.
     */
    public static int checksum(byte[] bytes, int offset, int length) {
        int sum = 0;
        int i = offset;
        int end = offset + length;
        for (; i + 1 < end; i += 2) {
            sum = (sum + (((bytes[i] & 0xFF) << 8) | (bytes[i + 1] & 0xFF))) & 0xFFFF;
        }
        if (i < end) {
            sum ^= bytes[i] & 0xFF;
        }
        return sum;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ArcosPacket p && Arrays.equals(data, p.data);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(data);
    }

    @Override
    public String toString() {
        return "ArcosPacket[type=0x" + Integer.toHexString(type()) + ", " + HexFormat.ofDelimiter(" ").formatHex(data) + "]";
    }
}
