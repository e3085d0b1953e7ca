package org.habla.sim.aibo;

import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Microphone Server (port 10070): one packet per 32 ms buffer of simulated time, paced by the
 * clock, each 512 stereo frames of 16 kHz 16-bit PCM:
 * <pre>
 * u16 size 2052 (bytes after the first 4) | u16 type 0 (PCM) | u16 rate 16000 | u8 bits 16 | u8 stereo 1
 * then 2048 bytes of samples, L, R interleaved, little-endian
 * </pre>
 * A client that does not read (one packet's write blocked for more than a second: the socket's buffer is full)
 * skips ahead rather than receive a backlog, and the skip is logged. When the simulator itself was late (its
 * thread starved on a busy machine) nothing is skipped: the sound happened, and the packets it owes go out at
 * once, as a robot's buffered microphone would send them.
 */
final class MicrophoneServer implements TekkotsuSocket.Client {

    private static final Logger LOG = LoggerFactory.getLogger(MicrophoneServer.class);

    static final int FRAMES_PER_PACKET = 512;
    static final int PACKET_BYTES = 8 + FRAMES_PER_PACKET * 4;
    private static final long MAX_LAG_SAMPLES = Microphone.RATE_HZ;

    private final Microphone microphone;
    private final AiboTime clock;

    MicrophoneServer(Microphone microphone, AiboTime clock) {
        this.microphone = microphone;
        this.clock = clock;
    }

    @Override
    public void serve(Socket socket) throws IOException, InterruptedException {
        TekkotsuSocket.closeWhenClientLeaves(socket);
        OutputStream out = socket.getOutputStream();
        long position = samplesAt(clock.nowMs());
        long skipped = 0;
        while (!socket.isClosed()) {
            long end = position + FRAMES_PER_PACKET;
            clock.sleepUntil((end * 1000 + Microphone.RATE_HZ - 1) / Microphone.RATE_HZ);
            long writing = System.nanoTime();
            out.write(packet(microphone.stereo(position, FRAMES_PER_PACKET)));
            out.flush();
            position = end;
            long now = samplesAt(clock.nowMs());
            if (System.nanoTime() - writing > 1_000_000_000L && now - position > MAX_LAG_SAMPLES) {
                skipped++;
                LOG.warn("microphone client {} does not read: skipped {} ms of sound ({} skips so far)",
                        socket.getRemoteSocketAddress(), (now - position) * 1000 / Microphone.RATE_HZ, skipped);
                position = now;
            }
        }
    }

    static long samplesAt(long ms) {
        return ms * Microphone.RATE_HZ / 1000;
    }

    static byte[] packet(short[] stereo) {
        ByteBuffer b = ByteBuffer.allocate(8 + stereo.length * 2).order(ByteOrder.LITTLE_ENDIAN);
        b.putShort((short) (4 + stereo.length * 2)).putShort((short) 0);
        b.putShort((short) Microphone.RATE_HZ).put((byte) 16).put((byte) 1);
        for (short s : stereo) {
            b.putShort(s);
        }
        return b.array();
    }
}
