package org.habla.sim.pioneer;

import java.io.BufferedInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.Consumer;
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
    private final ServerSocket listener;
    private volatile boolean closed;
    private volatile Client current;

    ArcosServer(PioneerController controller, int port) throws IOException {
        this.controller = controller;
        ServerSocket server = new ServerSocket();
        try {
            server.setReuseAddress(true);
            server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 4);
        } catch (IOException e) {
            server.close();
            throw new IOException("the simulated Pioneer cannot listen on 127.0.0.1:" + port + ": " + e.getMessage(), e);
        }
        listener = server;
        Thread acceptor = new Thread(this::acceptLoop, "arcos-accept");
        acceptor.setDaemon(true);
        acceptor.start();
        LOG.info("simulated Pioneer (ARCOS) listening on 127.0.0.1:{}", server.getLocalPort());
    }

    int port() {
        return listener.getLocalPort();
    }

    @Override
    public void close() {
        closed = true;
        try {
            listener.close();
        } catch (IOException e) {
            LOG.debug("closing the ARCOS port: {}", e.toString());
        }
        Client c = current;
        if (c != null) {
            c.close();
        }
    }

    private void acceptLoop() {
        while (!closed) {
            Socket socket;
            try {
                socket = listener.accept();
            } catch (IOException e) {
                if (!closed) {
                    LOG.warn("the ARCOS port stopped accepting: {}", e.toString());
                }
                return;
            }
            Client old = current;
            if (old != null) {
                LOG.info("a new ARCOS client from {} takes over from {}", socket.getRemoteSocketAddress(),
                        old.socket.getRemoteSocketAddress());
                old.close();
            }
            Client c = new Client(socket);
            current = c;
            controller.attach(c);
            Thread.ofVirtual().name("arcos-write").start(c::writeLoop);
            Thread.ofVirtual().name("arcos-read").start(c::readLoop);
        }
    }

    private final class Client implements Consumer<byte[]> {
        private final Socket socket;
        private final BlockingQueue<byte[]> outbox = new ArrayBlockingQueue<>(OUTBOX_PACKETS);
        private volatile boolean gone;
        private final LongAdder dropped = new LongAdder();

        Client(Socket socket) {
            this.socket = socket;
        }

        @Override
        public void accept(byte[] wire) {
            if (!gone && !outbox.offer(wire)) {
                dropped.increment();
            }
        }

        void readLoop() {
            ArcosFrames frames;
            try {
                frames = new ArcosFrames(new BufferedInputStream(socket.getInputStream()));
                while (!gone) {
                    controller.handle(frames.next());
                }
            } catch (EOFException e) {
                LOG.info("ARCOS client {} left: {}", socket.getRemoteSocketAddress(), e.getMessage());
            } catch (IOException e) {
                if (!gone) {
                    LOG.info("ARCOS client {} lost: {}", socket.getRemoteSocketAddress(), e.toString());
                }
            } catch (RuntimeException e) {
                LOG.warn("the simulated Pioneer failed on a packet; dropping the client", e);
            } finally {
                close();
            }
        }

        void writeLoop() {
            try {
                OutputStream out = socket.getOutputStream();
                while (!gone) {
                    byte[] wire = outbox.poll(200, TimeUnit.MILLISECONDS);
                    if (wire != null) {
                        out.write(wire);
                        if (outbox.isEmpty()) {
                            out.flush();
                        }
                    }
                }
            } catch (IOException e) {
                LOG.debug("ARCOS client write: {}", e.toString());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } finally {
                close();
            }
        }

        void close() {
            if (gone) {
                return;
            }
            gone = true;
            controller.detach(this);
            if (dropped.sum() > 0) {
                LOG.info("{} packets to the ARCOS client were dropped because it did not read them", dropped.sum());
            }
            try {
                socket.close();
            } catch (IOException e) {
                LOG.debug("closing an ARCOS client: {}", e.toString());
            }
        }
    }
}
