package org.habla.sim.pioneer;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.util.HexFormat;
import java.util.function.Predicate;
import org.habla.drivers.pioneer.ArcosPacket;
import org.habla.drivers.pioneer.StandardSip;

/** A bare ARCOS client for tests: sends hand-made packets, reads packets back with the simulator's own reader. */
final class RawArcosClient implements AutoCloseable {

    private final Socket socket;
    private final ArcosFrames frames;
    private final OutputStream out;

    RawArcosClient(int port) throws IOException {
        socket = new Socket(InetAddress.getLoopbackAddress(), port);
        socket.setSoTimeout(5_000);
        frames = new ArcosFrames(new BufferedInputStream(socket.getInputStream()));
        out = socket.getOutputStream();
    }

    /** Sends a packet given as hex data bytes, e.g. {@code "0B 3B 2C 01"} for VEL 300. */
    void send(String hexData) throws IOException {
        out.write(ArcosFrames.frame(HexFormat.ofDelimiter(" ").parseHex(hexData)));
        out.flush();
    }

    /** Sends an integer command the way the driver encodes it. */
    void send(int command, int argument) throws IOException {
        int m = Math.abs(argument);
        out.write(ArcosFrames.frame(new byte[] {(byte) command, (byte) (argument < 0 ? 0x1B : 0x3B), (byte) m,
                (byte) (m >> 8)}));
        out.flush();
    }

    /** How long (real ms) a read waits before it fails. */
    void timeout(int ms) throws IOException {
        socket.setSoTimeout(ms);
    }

    /** The next packet's data bytes. */
    byte[] next() throws IOException {
        return frames.next();
    }

    /** Syncs and opens. */
    void connect() throws IOException {
        for (String sync : new String[] {"00", "01", "02"}) {
            send(sync);
            next();
        }
        send("01");
    }

    /** The next SIP that satisfies {@code test}, skipping at most {@code max} packets. */
    StandardSip sip(Predicate<StandardSip> test, int max) throws IOException {
        for (int i = 0; i < max; i++) {
            byte[] data = next();
            if (StandardSip.isSip(data[0] & 0xFF)) {
                StandardSip sip = StandardSip.parse(ArcosPacket.of(data));
                if (test.test(sip)) {
                    return sip;
                }
            }
        }
        throw new AssertionError("no matching SIP among " + max + " packets");
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
