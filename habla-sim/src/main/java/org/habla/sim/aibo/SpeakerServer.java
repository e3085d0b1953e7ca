package org.habla.sim.aibo;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Speaker Server (port 10071), a sink: it takes the robot's sound and records it in the
 * {@link SpeakerLog}. The robot sends nothing back.
 * <pre>
 * u16 size (bytes after this 4-byte header) | u16 type (0 = PCM)
 * PCM body: u16 rate | u8 bits (8 unsigned or 16 signed LE) | u8 0 | size - 4 bytes of mono samples
 * </pre>
 * Other types, and PCM bodies too short for their header or with other sample sizes, are skipped by
 * their size and counted as rejected.
 */
final class SpeakerServer implements TekkotsuSocket.Client {

    private static final Logger LOG = LoggerFactory.getLogger(SpeakerServer.class);

    private final SpeakerLog log;
    private final AiboTime clock;

    SpeakerServer(SpeakerLog log, AiboTime clock) {
        this.log = log;
        this.clock = clock;
    }

    @Override
    public void serve(Socket socket) throws IOException {
        DataInputStream in = new DataInputStream(new BufferedInputStream(socket.getInputStream()));
        byte[] header = new byte[4];
        while (true) {
            try {
                in.readFully(header);
            } catch (EOFException e) {
                return;
            }
            ByteBuffer h = ByteBuffer.wrap(header).order(ByteOrder.LITTLE_ENDIAN);
            int size = h.getShort() & 0xffff;
            int type = h.getShort() & 0xffff;
            byte[] body = new byte[size];
            in.readFully(body);
            String problem = record(type, body);
            if (problem != null) {
                log.rejected();
                LOG.info("speaker server: skipped a packet ({})", problem);
            }
        }
    }

    private String record(int type, byte[] body) {
        if (type != 0) {
            return "type " + type + " is not PCM";
        }
        if (body.length < 4) {
            return "a PCM body of " + body.length + " bytes has no room for its header";
        }
        ByteBuffer b = ByteBuffer.wrap(body).order(ByteOrder.LITTLE_ENDIAN);
        int rate = b.getShort() & 0xffff;
        int bits = b.get() & 0xff;
        b.get();
        if (rate == 0 || (bits != 8 && bits != 16)) {
            return rate + " Hz, " + bits + " bits is not a format the speaker plays";
        }
        int samples = bits == 16 ? b.remaining() / 2 : b.remaining();
        double peak = 0;
        for (int i = 0; i < samples; i++) {
            double v = bits == 16 ? b.getShort() / 32768.0 : ((b.get() & 0xff) - 128) / 128.0;
            peak = Math.max(peak, Math.abs(v));
        }
        log.heard(rate, peak, samples, clock.nowS());
        return null;
    }
}
