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
 * until the connection fails, then waits ({@link BackOff}) and connects again — the cycle is the engine's
 * {@link ReconnectingLink}; this class is what is spoken over the socket. The connection fails when the
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
    /** Silence after which the peer is lost; 0 for a quiet peer (only TCP tells). */
    private final long silenceLimitMs;
    private final ReadingSink sink;
    private final ReentrantLock writeLock = new ReentrantLock();
    private final ReconnectingLink<RobotSession> link;
    private volatile double lastConnectMs = -1;

    ConnectionLink(String interfaceId, String host, Connection connection, Reconnect reconnect, ReadingSink sink,
            Runnable onStateChange) {
        this.name = interfaceId + "/" + connection.name();
        this.host = host;
        this.connection = connection;
        this.reconnect = reconnect;
        this.silenceLimitMs = connection.liveness() instanceof Liveness.Periodic p
                ? (reconnect.readTimeoutMs() > 0 ? reconnect.readTimeoutMs() : p.lostAfter().toMillis()) : 0;
        this.sink = sink;
        this.link = new ReconnectingLink<>(ReconnectingLink.THREAD_PREFIX + name, reconnect, RobotSession::new,
                new OutageLog(LOG, "link " + name + " (" + host + ":" + connection.port() + ")"),
                ReconnectingLink.StateListener.notifying(onStateChange));
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
        return link.up();
    }

    @Override
    public void start() {
        link.start();
    }

    /** Says goodbye if connected, closes the socket and stops reconnecting. */
    @Override
    public void stop() {
        link.stop();
    }

    /** The wait chooser of this link (tests and benchmarks observe the waits it chooses). */
    BackOff backOff() {
        return link.backOff();
    }

    /** Writes a command now; false if the connection is down or the write failed. */
    @Override
    public CommandResult command(String channel, Payload value) {
        return write("command " + channel, (s, o) -> s.write(channel, value, o));
    }

    @Override
    public boolean stopMotion() {
        CommandResult r = write("stop", (s, o) -> s.stopMotion(o));
        if (r.refusal() != null) {
            LOG.warn("link {}: stop refused: {}", name, r.refusal());
        }
        return r.written();
    }

    /** A refusal is the caller's to count and log (a command's dropped once, with its reason). */
    private CommandResult write(String what, SessionWrite action) {
        writeLock.lock();
        RobotSession session = link.session();
        try {
            if (session == null) {
                return CommandResult.DOWN;
            }
            action.write(session.protocol, session.out);
            session.out.flush();
            return CommandResult.WRITTEN;
        } catch (IllegalArgumentException e) {
            // The session refused to encode this command before writing a byte: drop it, keep the link.
            return CommandResult.refused(e.getMessage());
        } catch (IOException | RuntimeException e) {
            LOG.warn("link {}: {} failed, reconnecting: {}", name, what, e.toString());
            session.close();
            return CommandResult.refused("link " + name + " failed, reconnecting: " + e);
        } finally {
            writeLock.unlock();
        }
    }

    @Override
    public ObjectNode status() {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("name", connection.name());
        n.put("port", connection.port());
        n.put("up", link.up());
        n.put("liveness", silenceLimitMs > 0 ? "lost after " + silenceLimitMs + " ms of silence"
                : "quiet: silence is normal; TCP keep-alive");
        if (connection.optional()) {
            n.put("optional", true);
        }
        n.put("connects", link.connects());
        n.put("failures", link.failures());
        if (lastConnectMs >= 0) {
            n.put("lastConnectMs", Math.round(lastConnectMs * 10) / 10.0);
        }
        if (!link.lastError().isEmpty()) {
            n.put("lastError", link.lastError());
        }
        return n;
    }

    @Override
    public String lastError() {
        return link.lastError();
    }

    /** One TCP connection to the robot and the driver's session over it. */
    private final class RobotSession implements ReconnectingLink.Session {

        private volatile Socket socket;
        private volatile boolean closed;
        private volatile Thread keepAlive;
        private InputStream in;
        private LinkSession protocol;
        private OutputStream out;

        @Override
        public void open() throws IOException {
            Socket s = LinkSocket.create(reconnect.tcpKeepAlive());
            socket = s;
            if (closed) {
                s.close(); // the link was stopped before this socket existed: the connect below fails
            }
            long started = System.nanoTime();
            s.connect(new InetSocketAddress(host, connection.port()), (int) reconnect.connectTimeoutMs());
            s.setSoTimeout((int) reconnect.connectTimeoutMs());
            InputStream i = new BufferedInputStream(s.getInputStream());
            OutputStream o = new BufferedOutputStream(s.getOutputStream());
            LinkSession sess = connection.sessions().get();
            sess.handshake(i, o, sink);
            o.flush();
            s.setSoTimeout((int) silenceLimitMs);
            in = i;
            protocol = sess;
            out = o;
            lastConnectMs = (System.nanoTime() - started) / 1e6;
            sess.keepAlivePeriod().ifPresent(p -> keepAlive = startKeepAlive(p.toMillis()));
        }

        @Override
        public void readNext() throws IOException {
            try {
                protocol.readNext(in, sink);
            } catch (SocketTimeoutException e) {
                throw new IOException("nothing came for " + silenceLimitMs + " ms from a peer that keeps sending: lost");
            }
        }

        @Override
        public void goodbye() {
            write("goodbye", (s, o) -> s.goodbye(o));
        }

        /** Keep-alives go from a thread of their own, so a robot that stops reading blocks nothing else. */
        private Thread startKeepAlive(long periodMillis) {
            return Thread.ofVirtual().name("habla-keepalive-" + name).start(() -> {
                while (link.running() && !closed) {
                    try {
                        Thread.sleep(Math.max(1, periodMillis));
                    } catch (InterruptedException e) {
                        return;
                    }
                    if (link.session() == this) {
                        write("keep-alive", (x, w) -> x.keepAlive(w));
                    }
                }
            });
        }

        @Override
        public void close() {
            closed = true;
            Thread k = keepAlive;
            if (k != null) {
                k.interrupt();
            }
            Socket s = socket;
            if (s != null) {
                try {
                    s.close();
                } catch (IOException e) {
                    LOG.debug("closing {}: {}", name, e.toString());
                }
            }
        }
    }

    @FunctionalInterface
    private interface SessionWrite {
        void write(LinkSession session, OutputStream out) throws IOException;
    }
}
