package org.habla.sim.aibo;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import org.habla.driver.Connection;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;

/**
 * Runs one connection of a real HABLA driver against the simulator the way the engine does: connect,
 * handshake, a reader calling {@code readNext}, keep-alives, writes under a lock, and a new connection
 * 100 ms after the old one ends (a Tekkotsu server that is still off closes at once).
 */
final class DriverLink implements AutoCloseable {

    private final Connection connection;
    private final ReadingSink sink;
    private final Thread runner;
    private final AtomicInteger sessions = new AtomicInteger();
    private volatile boolean closed;
    private volatile Socket socket;
    private volatile LinkSession session;
    private volatile OutputStream out;

    DriverLink(Connection connection, ReadingSink sink) {
        this.connection = connection;
        this.sink = sink;
        this.runner = Thread.ofVirtual().name("link-" + connection.name()).start(this::run);
    }

    private void run() {
        while (!closed) {
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress("127.0.0.1", connection.port()), 1_000);
                s.setSoTimeout(0);
                InputStream in = new BufferedInputStream(s.getInputStream());
                LinkSession next = connection.sessions().get();
                synchronized (this) {
                    socket = s;
                    out = new BufferedOutputStream(s.getOutputStream());
                    next.handshake(in, out, sink);
                    out.flush();
                    session = next;
                }
                sessions.incrementAndGet();
                Thread keepAlive = Thread.ofVirtual().start(() -> keepAlive(next, s));
                try {
                    while (!closed) {
                        next.readNext(in, sink);
                    }
                } finally {
                    keepAlive.interrupt();
                }
            } catch (IOException | RuntimeException e) {
                // the engine would reconnect with back-off; so does this link
            }
            synchronized (this) {
                session = null;
            }
            sleep(100);
        }
    }

    private void keepAlive(LinkSession s, Socket sock) {
        s.keepAlivePeriod().ifPresent(period -> {
            while (!sock.isClosed()) {
                sleep(period.toMillis());
                try {
                    synchronized (this) {
                        if (session == s) {
                            s.keepAlive(out);
                            out.flush();
                        }
                    }
                } catch (IOException e) {
                    return;
                }
            }
        });
    }

    /** Whether a session is up now. */
    boolean up() {
        return session != null;
    }

    int sessionCount() {
        return sessions.get();
    }

    /** Sends a command through the current session; false when the link is down. */
    synchronized boolean write(String channel, Payload value) throws IOException {
        if (session == null) {
            return false;
        }
        session.write(channel, value, out);
        out.flush();
        return true;
    }

    @Override
    public void close() {
        closed = true;
        synchronized (this) {
            if (session != null) {
                try {
                    session.goodbye(out);
                    out.flush();
                } catch (IOException e) {
                    // gone already
                }
            }
        }
        Socket s = socket;
        if (s != null) {
            try {
                s.close();
            } catch (IOException e) {
                // closing
            }
        }
        runner.interrupt();
        try {
            runner.join(2_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Polls {@code condition} every 10 ms until it holds or {@code limit} passes. */
    static boolean await(Duration limit, BooleanSupplier condition) {
        long deadline = System.nanoTime() + limit.toNanos();
        while (System.nanoTime() < deadline) {
            if (condition.getAsBoolean()) {
                return true;
            }
            sleep(10);
        }
        return condition.getAsBoolean();
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
