package org.habla.sim.aibo;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One of the simulated Aibo's server sockets on loopback. Like Tekkotsu's daemon sockets it serves one
 * client at a time and listens again when that client leaves; a second client is closed at once.
 *
 * <p>A Tekkotsu server exists only while its behaviour runs. The socket stays bound for the life of the
 * simulator (so its port never changes), but while the server is switched off every connection is
 * closed as soon as it is accepted: a client sees the connection end and tries again later, as it would
 * after a refusal.
 */
final class TekkotsuSocket implements AutoCloseable {

    /** Serves one connected client until it leaves or the server is switched off. */
    @FunctionalInterface
    interface Client {
        void serve(Socket socket) throws IOException, InterruptedException;
    }

    private static final Logger LOG = LoggerFactory.getLogger(TekkotsuSocket.class);

    private final String name;
    private final ServerSocket listener;
    private final Client client;
    private final Thread acceptor;
    private volatile boolean on;
    private Socket current;
    private Thread serving;

    TekkotsuSocket(String name, int port, boolean onAtBoot, Client client) throws IOException {
        this.name = name;
        this.client = client;
        this.on = onAtBoot;
        this.listener = new ServerSocket();
        listener.setReuseAddress(true);
        listener.bind(new java.net.InetSocketAddress(InetAddress.getLoopbackAddress(), port), 4);
        this.acceptor = Thread.ofVirtual().name("aibo-" + name).start(this::acceptLoop);
    }

    String name() {
        return name;
    }

    int port() {
        return listener.getLocalPort();
    }

    boolean isOn() {
        return on;
    }

    /** Switches the server on (its behaviour started) or off (stopped: the client is dropped). */
    void switchOn(boolean running) {
        Socket drop = null;
        Thread stop = null;
        synchronized (this) {
            on = running;
            if (!running) {
                drop = current;
                stop = serving;
            }
        }
        closeQuietly(drop);
        if (stop != null) {
            stop.interrupt();
        }
    }

    private void acceptLoop() {
        while (!listener.isClosed()) {
            Socket s;
            try {
                s = listener.accept();
            } catch (IOException e) {
                return;
            }
            boolean take;
            synchronized (this) {
                take = on && current == null;
                if (take) {
                    current = s;
                }
            }
            if (!take) {
                closeQuietly(s);
                continue;
            }
            synchronized (this) {
                serving = Thread.ofVirtual().name("aibo-" + name + "-client").start(() -> serve(s));
            }
        }
    }

    private void serve(Socket s) {
        try {
            s.setTcpNoDelay(true);
            client.serve(s);
        } catch (SocketException e) {
            LOG.debug("{}: client {} left: {}", name, s.getRemoteSocketAddress(), e.getMessage());
        } catch (IOException e) {
            LOG.info("{}: client {} dropped: {}", name, s.getRemoteSocketAddress(), e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            LOG.warn("{}: client {} dropped after an internal error", name, s.getRemoteSocketAddress(), e);
        } finally {
            closeQuietly(s);
            synchronized (this) {
                if (current == s) {
                    current = null;
                    serving = null;
                }
            }
        }
    }

    /**
     * For a server that only sends: reads and discards whatever the client sends and closes the socket when
     * the client leaves, so a client that has gone frees the port at once rather than at the next failed write.
     */
    static void closeWhenClientLeaves(Socket s) {
        Thread.ofVirtual().start(() -> {
            try {
                s.getInputStream().transferTo(java.io.OutputStream.nullOutputStream());
            } catch (IOException e) {
                // closed under us: the same outcome
            }
            closeQuietly(s);
        });
    }

    @Override
    public void close() {
        closeQuietly(listener);
        switchOn(false);
        acceptor.interrupt();
    }

    private static void closeQuietly(AutoCloseable c) {
        if (c == null) {
            return;
        }
        try {
            c.close();
        } catch (Exception e) {
            // closing anyway
        }
    }
}
