package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;
import org.habla.config.Reconnect;
import org.habla.driver.Connection;
import org.habla.driver.LinkSession;
import org.habla.driver.Liveness;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Keeps one TCP connection of an interface alive: connects, runs the driver session's handshake, reads
 * until the connection fails, then waits ({@link BackOff}) and connects again. The connection fails when the
 * peer closes or resets it, when TCP keep-alive finds its host gone ({@link LinkSocket}), or — only if the
 * driver declares the peer's stream periodic ({@link Liveness}) — after the stream's silence limit; a quiet
 * peer may be silent for ever. Writes come from any thread and are serialised; a write to a connection that
 * is down is refused, never queued, so a command is never applied late.
 */
final class ConnectionLink implements Link {

    private static final Logger LOG = LoggerFactory.getLogger(ConnectionLink.class);

    private final String name;
    private final String host;
    private final Connection connection;
    private final Reconnect reconnect;
    private final BackOff backOff;
    /** Silence after which the peer is lost; 0 for a quiet peer (only TCP tells). */
    private final long silenceLimitMs;
    private final OutageLog outages;
    private final ReadingSink sink;
    private final Runnable onStateChange;
    private final ReentrantLock writeLock = new ReentrantLock();
    private final AtomicLong connects = new AtomicLong();
    private final AtomicLong failures = new AtomicLong();
    private volatile boolean running;
    private volatile boolean up;
    private volatile String lastError = "";
    private volatile double lastConnectMs = -1;
    private volatile Socket socket;
    private volatile LinkSession session;
    private volatile OutputStream out;
    private AutoCloseable keepAlive;
    private Thread thread;

    ConnectionLink(String interfaceId, String host, Connection connection, Reconnect reconnect, ReadingSink sink,
            Runnable onStateChange) {
        this.name = interfaceId + "/" + connection.name();
        this.host = host;
        this.connection = connection;
        this.reconnect = reconnect;
        this.backOff = new BackOff(reconnect);
        this.silenceLimitMs = connection.liveness() instanceof Liveness.Periodic p
                ? (reconnect.readTimeoutMs() > 0 ? reconnect.readTimeoutMs() : p.lostAfter().toMillis()) : 0;
        this.outages = new OutageLog(LOG, "link " + name + " (" + host + ":" + connection.port() + ")");
        this.sink = sink;
        this.onStateChange = onStateChange;
    }

    @Override
    public String connectionName() {
        return connection.name();
    }

    @Override
    public boolean optional() {
        return connection.optional();
    }

    @Override
    public java.util.Set<String> commandChannels() {
        return connection.commandChannels();
    }

    @Override
    public boolean up() {
        return up;
    }

    @Override
    public void start() {
        running = true;
        thread = Thread.ofVirtual().name("habla-link-" + name).start(this::loop);
    }

    /** Says goodbye if connected, closes the socket and stops reconnecting. */
    @Override
    public void stop() {
        running = false;
        if (up) {
            write("goodbye", (s, o) -> s.goodbye(o));
        }
        closeSocket();
        backOff.wake();
        if (thread != null) {
            try {
                thread.join(2_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** The wait chooser of this link (tests and benchmarks observe the waits it chooses). */
    BackOff backOff() {
        return backOff;
    }

    private void loop() {
        while (running) {
            Exception failure;
            try {
                runOnce();
                break;
            } catch (IOException | RuntimeException e) {
                failure = e;
                if (running) {
                    failures.incrementAndGet();
                    lastError = e.getMessage() == null ? e.toString() : e.getMessage();
                    outages.failed(lastError);
                }
            } finally {
                markDown();
            }
            if (running && !backOff.pause(failure, () -> running)) {
                running = false;
            }
        }
    }

    private void runOnce() throws IOException {
        Socket s = LinkSocket.create(reconnect.tcpKeepAlive());
        socket = s;
        long started = System.nanoTime();
        s.connect(new InetSocketAddress(host, connection.port()), (int) reconnect.connectTimeoutMs());
        s.setSoTimeout((int) reconnect.connectTimeoutMs());
        InputStream in = new BufferedInputStream(s.getInputStream());
        OutputStream o = new BufferedOutputStream(s.getOutputStream());
        LinkSession sess = connection.sessions().get();
        sess.handshake(in, o, sink);
        o.flush();
        s.setSoTimeout((int) silenceLimitMs);
        session = sess;
        out = o;
        connects.incrementAndGet();
        lastConnectMs = (System.nanoTime() - started) / 1e6;
        up = true;
        lastError = "";
        backOff.reset();
        outages.up();
        onStateChange.run();
        sess.keepAlivePeriod().ifPresent(p -> keepAlive = startKeepAlive(sess, p.toMillis()));
        while (running) {
            try {
                sess.readNext(in, sink);
            } catch (SocketTimeoutException e) {
                throw new IOException("nothing came for " + silenceLimitMs + " ms from a peer that keeps sending: lost");
            }
        }
    }

    private void markDown() {
        closeKeepAlive();
        boolean was = up;
        up = false;
        session = null;
        out = null;
        closeSocket();
        if (was) {
            onStateChange.run();
        }
    }

    /** Keep-alives go from a thread of their own, so a robot that stops reading blocks nothing else. */
    private AutoCloseable startKeepAlive(LinkSession sess, long periodMillis) {
        Thread t = Thread.ofVirtual().name("habla-keepalive-" + name).start(() -> {
            while (running && session == sess) {
                try {
                    Thread.sleep(Math.max(1, periodMillis));
                } catch (InterruptedException e) {
                    return;
                }
                if (session == sess) {
                    write("keep-alive", (x, w) -> x.keepAlive(w));
                }
            }
        });
        return t::interrupt;
    }

    private void closeKeepAlive() {
        AutoCloseable k = keepAlive;
        keepAlive = null;
        if (k != null) {
            try {
                k.close();
            } catch (Exception e) {
                LOG.debug("keep-alive of {} did not close: {}", name, e.toString());
            }
        }
    }

    private void closeSocket() {
        Socket s = socket;
        if (s != null) {
            try {
                s.close();
            } catch (IOException e) {
                LOG.debug("closing {}: {}", name, e.toString());
            }
        }
    }


    /** Writes a command now; false if the connection is down or the write failed. */
    @Override
    public boolean command(String channel, Payload value) {
        return write("command " + channel, (s, o) -> s.write(channel, value, o));
    }

    @Override
    public boolean stopMotion() {
        return write("stop", (s, o) -> s.stopMotion(o));
    }

    private boolean write(String what, SessionWrite action) {
        writeLock.lock();
        try {
            LinkSession s = session;
            OutputStream o = out;
            if (!up || s == null || o == null) {
                return false;
            }
            action.write(s, o);
            o.flush();
            return true;
        } catch (IllegalArgumentException e) {
            // The session refused to encode this command before writing a byte: drop it, keep the link.
            LOG.warn("link {}: {} refused: {}", name, what, e.getMessage());
            return false;
        } catch (IOException | RuntimeException e) {
            LOG.warn("link {}: {} failed, reconnecting: {}", name, what, e.toString());
            closeSocket();
            return false;
        } finally {
            writeLock.unlock();
        }
    }

    @Override
    public ObjectNode status() {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("name", connection.name());
        n.put("port", connection.port());
        n.put("up", up);
        n.put("liveness", silenceLimitMs > 0 ? "lost after " + silenceLimitMs + " ms of silence"
                : "quiet: silence is normal; TCP keep-alive");
        if (connection.optional()) {
            n.put("optional", true);
        }
        n.put("connects", connects.get());
        n.put("failures", failures.get());
        if (lastConnectMs >= 0) {
            n.put("lastConnectMs", Math.round(lastConnectMs * 10) / 10.0);
        }
        if (!lastError.isEmpty()) {
            n.put("lastError", lastError);
        }
        return n;
    }

    @Override
    public String lastError() {
        return lastError;
    }

    @FunctionalInterface
    private interface SessionWrite {
        void write(LinkSession session, OutputStream out) throws IOException;
    }
}
