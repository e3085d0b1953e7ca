package org.habla.sim.pioneer;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;

/**
 * The robot's side of ARCOS framing: it frames the packets it sends and finds the client's packets in the byte
 * stream, resynchronising after garbage.
 *
 * <pre>
 *  +------+------+-------+--------------------------------+----------+---------+
 *  | 0xFA | 0xFB | count | data: command/type, args (N)   | sum high | sum low |
 *  +------+------+-------+--------------------------------+----------+---------+
 *                  count = N + 2; checksum = 16-bit sum of the data taken as big-endian pairs,
 *                  an odd last byte XORed into the low byte; transmitted high byte first
 * </pre>
 *
 * Like the controller, the reader trusts nothing: it hunts for {@code FA FB}, reads the count, and drops a packet
 * whose count is out of range or whose checksum is wrong, then hunts again. A client that vanishes in the middle
 * of a packet ends the stream ({@link EOFException}); what came before is unaffected.
 */
final class ArcosFrames {

    static final int HEADER_1 = 0xFA;
    static final int HEADER_2 = 0xFB;
    /** Largest count byte sent; the robot accepts up to 255 on receive. */
    static final int MAX_SEND_COUNT = 200;

    private final InputStream in;
    private long dropped;

    ArcosFrames(InputStream in) {
        this.in = in;
    }

    /** Frames {@code data} (command or type byte first) for the wire. */
    static byte[] frame(byte[] data) {
        if (data.length < 1 || data.length + 2 > MAX_SEND_COUNT) {
            throw new IllegalArgumentException("a packet carries 1.." + (MAX_SEND_COUNT - 2) + " data bytes, not "
                    + data.length);
        }
        byte[] wire = new byte[data.length + 5];
        wire[0] = (byte) HEADER_1;
        wire[1] = (byte) HEADER_2;
        wire[2] = (byte) (data.length + 2);
        System.arraycopy(data, 0, wire, 3, data.length);
        int sum = checksum(data, data.length);
        wire[wire.length - 2] = (byte) (sum >>> 8);
        wire[wire.length - 1] = (byte) sum;
        return wire;
    }

    static int checksum(byte[] data, int length) {
        int sum = 0;
        int i = 0;
        for (; i + 1 < length; i += 2) {
            sum = (sum + (((data[i] & 0xFF) << 8) | (data[i + 1] & 0xFF))) & 0xFFFF;
        }
        if (i < length) {
            sum ^= data[i] & 0xFF;
        }
        return sum;
    }

    /** Packets dropped so far for a bad count or checksum. */
    long dropped() {
        return dropped;
    }

    /**
     * The data bytes of the client's next good packet.
     *
     * @throws EOFException when the client closes the connection, between or inside packets
     */
    byte[] next() throws IOException {
        while (true) {
            int b = read();
            if (b != HEADER_1) {
                continue;
            }
            int b2 = read();
            while (b2 == HEADER_1) {
                b2 = read();
            }
            if (b2 != HEADER_2) {
                continue;
            }
            int count = read();
            if (count < 3) {
                dropped++;
                continue;
            }
            byte[] body = in.readNBytes(count);
            if (body.length < count) {
                throw new EOFException("the client left inside a packet");
            }
            int n = count - 2;
            int sum = ((body[n] & 0xFF) << 8) | (body[n + 1] & 0xFF);
            if (sum != checksum(body, n)) {
                dropped++;
                continue;
            }
            return Arrays.copyOf(body, n);
        }
    }

    private int read() throws IOException {
        int b = in.read();
        if (b < 0) {
            throw new EOFException("the client closed the connection");
        }
        return b;
    }
}
