package org.habla.sim.pioneer;

import java.io.IOException;
import java.io.InputStream;
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
 * A loopback TCP port that serves one client at a time, like a robot's one serial line or a laptop's
 * {@code nc -l}: a new client takes the port over from the old one. Each client has a writer that drains a
 * bounded outbox, so a client that stops reading loses data (counted) instead of stalling the simulation, and a
 * reader that the port's owner supplies.
 */
final class OneClientPort implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(OneClientPort.class);

    /** What the port's owner does with a client's input; returns (or throws) when the client is gone. */
    @FunctionalInterface
    interface Reader {
        void read(Client client, InputStream in) throws IOException;
    }

    private final String what;
    private final int outboxSize;
    private final Reader reader;
    private final Consumer<Client> attached;
    private final Consumer<Client> detached;
    private final ServerSocket listener;
    private final LongAdder dropped = new LongAdder();
    private volatile boolean closed;
    private volatile Client current;

    /**
     * @param what     what the port is, for log lines and errors ("the simulated Pioneer (ARCOS)")
     * @param name     a short name for its threads ("arcos")
     * @param attached told of each new client, before its reader starts
     * @param detached told once when a client goes
     */
    OneClientPort(String what, String name, int port, int outboxSize, Reader reader, Consumer<Client> attached,
            Consumer<Client> detached) throws IOException {
        this.what = what;
        this.outboxSize = outboxSize;
        this.reader = reader;
        this.attached = attached;
        this.detached = detached;
        ServerSocket server = new ServerSocket();
        try {
            server.setReuseAddress(true);
            server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 4);
        } catch (IOException e) {
            server.close();
            throw new IOException(what + " cannot listen on 127.0.0.1:" + port + ": " + e.getMessage(), e);
        }
        listener = server;
        Thread acceptor = new Thread(() -> acceptLoop(name), name + "-accept");
        acceptor.setDaemon(true);
        acceptor.start();
    }

    int port() {
        return listener.getLocalPort();
    }

    /** Whether a client is connected. */
    boolean connected() {
        return current != null;
    }

    /** Hands bytes to the current client, if there is one; never blocks. */
    void send(byte[] bytes) {
        Client c = current;
        if (c != null) {
            c.accept(bytes);
        }
    }

    /** Writes dropped because a client did not read them in time, since the start. */
    long dropped() {
        return dropped.sum();
    }

    @Override
    public void close() {
        closed = true;
        try {
            listener.close();
        } catch (IOException e) {
            LOG.debug("closing {}: {}", what, e.toString());
        }
        Client c = current;
        if (c != null) {
            c.close();
        }
    }

    private void acceptLoop(String name) {
        while (!closed) {
            Socket socket;
            try {
                socket = listener.accept();
            } catch (IOException e) {
                if (!closed) {
                    LOG.warn("{} stopped accepting: {}", what, e.toString());
                }
                return;
            }
            Client old = current;
            if (old != null) {
                LOG.info("a new client of {} from {} takes over from {}", what, socket.getRemoteSocketAddress(),
                        old.socket.getRemoteSocketAddress());
                old.close();
            }
            Client c = new Client(socket);
            current = c;
            attached.accept(c);
            Thread.ofVirtual().name(name + "-write").start(c::writeLoop);
            Thread.ofVirtual().name(name + "-read").start(c::readLoop);
        }
    }

    /** One connected client: it takes bytes to send as a {@code Consumer<byte[]>}. */
    final class Client implements Consumer<byte[]> {
        private final Socket socket;
        private final BlockingQueue<byte[]> outbox = new ArrayBlockingQueue<>(outboxSize);
        private final LongAdder mine = new LongAdder();
        private volatile boolean gone;

        private Client(Socket socket) {
            this.socket = socket;
        }

        @Override
        public void accept(byte[] bytes) {
            if (!gone && !outbox.offer(bytes)) {
                mine.increment();
                dropped.increment();
            }
        }

        private void readLoop() {
            try {
                reader.read(this, socket.getInputStream());
            } catch (IOException e) {
                if (!gone) {
                    LOG.info("client {} of {} left: {}", socket.getRemoteSocketAddress(), what, e.toString());
                }
            } catch (RuntimeException e) {
                LOG.warn("{} failed on a client's input; dropping the client", what, e);
            } finally {
                close();
            }
        }

        private void writeLoop() {
            try {
                OutputStream out = socket.getOutputStream();
                while (!gone) {
                    byte[] bytes = outbox.poll(200, TimeUnit.MILLISECONDS);
                    if (bytes != null) {
                        out.write(bytes);
                        if (outbox.isEmpty()) {
                            out.flush();
                        }
                    }
                }
            } catch (IOException e) {
                if (!gone) {
                    LOG.info("client {} of {} left: {}", socket.getRemoteSocketAddress(), what, e.toString());
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } finally {
                close();
            }
        }

        boolean gone() {
            return gone;
        }

        void close() {
            synchronized (this) {
                if (gone) {
                    return;
                }
                gone = true;
            }
            if (current == this) {
                current = null;
            }
            detached.accept(this);
            if (mine.sum() > 0) {
                LOG.info("{} writes to a client of {} were dropped because it did not read them", mine.sum(), what);
            }
            try {
                socket.close();
            } catch (IOException e) {
                LOG.debug("closing a client of {}: {}", what, e.toString());
            }
        }
    }
}
