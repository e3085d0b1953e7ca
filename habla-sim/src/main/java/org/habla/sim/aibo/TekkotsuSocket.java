package org.habla.sim.aibo;

import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One of the simulated Aibo's server sockets on loopback. Like Tekkotsu's daemon sockets it serves one
 * client at a time and listens again when that client leaves; a second client is closed at once.
 *
 * <p>A Tekkotsu server exists only while its behaviour runs: switched off, the port is closed and a
 * client's connection is refused, as on the robot. The port is chosen once (port 0 takes a free one)
 * and reused every time the server is switched on again.
 */
final class TekkotsuSocket implements AutoCloseable {

    /** Serves one connected client until it leaves or the server is switched off. */
    @FunctionalInterface
    interface Client {
        void serve(Socket socket) throws IOException, InterruptedException;
    }

    private static final Logger LOG = LoggerFactory.getLogger(TekkotsuSocket.class);

    private final String name;
    private final int port;
    private final Client client;
    private ServerSocket listener;
    private Socket current;
    private Thread serving;
    private boolean closed;
    /** The first socket of a server off at boot, kept until every server has its port (see {@link #releaseReservation}). */
    private ServerSocket reserved;

    TekkotsuSocket(String name, int port, boolean onAtBoot, Client client) throws IOException {
        this.name = name;
        this.client = client;
        ServerSocket first = bind(port);
        this.port = first.getLocalPort();
        if (onAtBoot) {
            listen(first);
        } else {
            reserved = first;
        }
    }

    /**
     * Closes the socket that held the port of a server off at boot. Until then a free port chosen for it cannot
     * be handed out again to another server of the same robot.
     */
    synchronized void releaseReservation() {
        closeQuietly(reserved);
        reserved = null;
    }

    String name() {
        return name;
    }

    int port() {
        return port;
    }

    synchronized boolean isOn() {
        return listener != null;
    }

    /** Switches the server on (its behaviour started: the port listens) or off (the port closes, the client is dropped). */
    void switchOn(boolean running) {
        Socket drop = null;
        Thread stop = null;
        ServerSocket shut = null;
        synchronized (this) {
            if (closed || running == (listener != null)) {
                return;
            }
            if (running) {
                try {
                    ServerSocket held = reserved;
                    reserved = null;
                    listen(held != null ? held : bind(port));
                } catch (IOException e) {
                    LOG.warn("{}: cannot listen on port {} again: {}", name, port, e.getMessage());
                }
                return;
            }
            shut = listener;
            listener = null;
            drop = current;
            stop = serving;
        }
        closeQuietly(shut);
        closeQuietly(drop);
        if (stop != null) {
            stop.interrupt();
        }
    }

    private static ServerSocket bind(int port) throws IOException {
        ServerSocket s = new ServerSocket();
        s.setReuseAddress(true);
        try {
            s.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 4);
        } catch (IOException e) {
            s.close();
            throw e;
        }
        return s;
    }

    private synchronized void listen(ServerSocket s) {
        listener = s;
        Thread.ofVirtual().name("aibo-" + name).start(() -> acceptLoop(s));
    }

    private void acceptLoop(ServerSocket s) {
        while (!s.isClosed()) {
            Socket c;
            try {
                c = s.accept();
            } catch (IOException e) {
                return;
            }
            synchronized (this) {
                if (listener == s && current == null) {
                    current = c;
                    serving = Thread.ofVirtual().name("aibo-" + name + "-client").start(() -> serve(c));
                    continue;
                }
            }
            closeQuietly(c);
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
                s.getInputStream().transferTo(OutputStream.nullOutputStream());
            } catch (IOException e) {
                // closed under us: the same outcome
            }
            closeQuietly(s);
        });
    }

    @Override
    public void close() {
        releaseReservation();
        switchOn(false);
        synchronized (this) {
            closed = true;
        }
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
