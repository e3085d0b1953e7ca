package org.habla.sim.aibo;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;

/**
 * The World State Serializer (port 10031): one 374-byte ERS-7 packet per 32 ms sensor update of
 * simulated time (or per {@code main.worldState_interval}), timestamps in simulated milliseconds since
 * boot, the frame number advancing by 4 per update as OPEN-R counts 8 ms frames. Nothing is read.
 */
final class WorldStateServer implements TekkotsuSocket.Client {

    /** OPEN-R delivers sensors every 4 frames of 8 ms. */
    static final long SENSOR_PERIOD_MS = 32;

    private final Ers7Body body;
    private final AiboTime clock;
    private final RobotSettings settings;

    WorldStateServer(Ers7Body body, AiboTime clock, RobotSettings settings) {
        this.body = body;
        this.clock = clock;
        this.settings = settings;
    }

    @Override
    public void serve(Socket socket) throws IOException, InterruptedException {
        TekkotsuSocket.closeWhenClientLeaves(socket);
        OutputStream out = new BufferedOutputStream(socket.getOutputStream(), Ers7Layout.PACKET_BYTES * 2);
        long update = clock.nowMs() / SENSOR_PERIOD_MS + 1;
        while (!socket.isClosed()) {
            long interval = Math.max(1, (settings.worldStateIntervalMs() + SENSOR_PERIOD_MS - 1) / SENSOR_PERIOD_MS);
            long at = update * SENSOR_PERIOD_MS;
            clock.sleepUntil(at);
            out.write(Ers7Layout.encode(body.snapshot(at), at, update * 4));
            out.flush();
            long now = clock.nowMs() / SENSOR_PERIOD_MS;
            // a slow client gets the newest update, not a backlog
            update = Math.max(update + interval, now);
        }
    }
}
