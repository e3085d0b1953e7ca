package org.habla.sim.pioneer;

import java.io.BufferedInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulated Pioneer's TCP port (8101 by default, as MobileSim and AMRISim): one client at a time, like the
 * robot's one serial port. A new client takes the port over from an old one. Each connection has a reader that
 * finds packets in the byte stream and hands them to the {@link PioneerController}, and a writer that drains a
 * bounded queue of outgoing packets, so a client that stops reading loses SIPs instead of stalling the simulation.
 */
final class ArcosServer implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(ArcosServer.class);
    /** Packets waiting for the client before new ones are dropped (5 s of SIPs). */
    static final int OUTBOX_PACKETS = 50;

    private final PioneerController controller;
    private final OneClientPort port;

    ArcosServer(PioneerController controller, int port) throws IOException {
        this.controller = controller;
        this.port = new OneClientPort("the simulated Pioneer (ARCOS)", "arcos", port, OUTBOX_PACKETS, this::read,
                controller::attach, controller::detach);
        LOG.info("simulated Pioneer (ARCOS) listening on 127.0.0.1:{}", this.port.port());
    }

    int port() {
        return port.port();
    }

    private void read(OneClientPort.Client client, InputStream in) throws IOException {
        ArcosFrames frames = new ArcosFrames(new BufferedInputStream(in));
        try {
            while (!client.gone()) {
                controller.handle(frames.next());
            }
        } catch (EOFException e) {
            LOG.info("an ARCOS client left: {}", e.getMessage());
        }
    }

    @Override
    public void close() {
        port.close();
    }
}
