package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.time.Duration;
import java.util.Set;
import java.util.concurrent.locks.ReentrantLock;
import org.habla.config.Reconnect;
import org.habla.driver.ClientConnection;
import org.habla.driver.ClientSession;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Keeps one connection that a client library opens itself (a {@link ClientSession}): opens it, reads until it
 * is lost, closes it, waits with the engine's {@link BackOff} and opens a fresh session — the cycle is the
 * engine's {@link ReconnectingLink}. The wait starts again from the shortest once a session has been up. Writes
 * come from any thread and are serialised; a write while the connection is down is refused, never queued, so a
 * command is never applied late.
 */
final class ClientLink implements Link {

    private static final Logger LOG = LoggerFactory.getLogger(ClientLink.class);

    private final String name;
    private final ClientConnection connection;
    private final Reconnect reconnect;
    private final ReadingSink sink;
    private final ReentrantLock writeLock = new ReentrantLock();
    private final ReconnectingLink<Attempt> link;

    ClientLink(String interfaceId, ClientConnection connection, Reconnect reconnect, ReadingSink sink,
            Runnable onStateChange) {
        this.name = interfaceId + "/" + connection.name();
        this.connection = connection;
        this.reconnect = reconnect;
        this.sink = sink;
        this.link = new ReconnectingLink<>(ReconnectingLink.THREAD_PREFIX + name, reconnect, Attempt::new,
                new OutageLog(LOG, "link " + name),
                ReconnectingLink.StateListener.notifying(onStateChange, writeLock)); // a write ends before its close
    }

    @Override
    public String connectionName() {
        return connection.name();
    }

    @Override
    public Set<String> commandChannels() {
        return connection.commandChannels();
    }

    @Override
    public boolean up() {
        return link.up();
    }

    @Override
    public String lastError() {
        return link.lastError();
    }

    @Override
    public void start() {
        link.start();
    }

    @Override
    public void stop() {
        link.stop();
    }

    @Override
    public CommandResult command(String channel, Payload value) {
        return write("command " + channel, s -> s.write(channel, value));
    }

    @Override
    public boolean stopMotion() {
        CommandResult r = write("stop", ClientSession::stopMotion);
        if (r.refusal() != null) {
            LOG.warn("link {}: stop refused: {}", name, r.refusal());
        }
        return r.written();
    }

    /** A refusal is the caller's to count and log (a command's dropped once, with its reason). */
    private CommandResult write(String what, SessionWrite action) {
        writeLock.lock();
        Attempt attempt = link.session();
        try {
            if (attempt == null) {
                return CommandResult.DOWN;
            }
            action.write(attempt.session);
            return CommandResult.WRITTEN;
        } catch (IllegalArgumentException e) {
            // The session refused the command (e.g. its device is offline): drop it, keep the link.
            return CommandResult.refused(e.getMessage());
        } catch (IOException | RuntimeException e) {
            LOG.warn("link {}: {} failed, reconnecting: {}", name, what, e.toString());
            attempt.close();
            return CommandResult.refused("link " + name + " failed, reconnecting: " + e);
        } finally {
            writeLock.unlock();
        }
    }

    @Override
    public ObjectNode status() {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("name", connection.name());
        n.put("up", link.up());
        n.put("connects", link.connects());
        n.put("failures", link.failures());
        if (!link.lastError().isEmpty()) {
            n.put("lastError", link.lastError());
        }
        return n;
    }

    /** One session of the client library, for one attempt. */
    private final class Attempt implements ReconnectingLink.Session {

        private final ClientSession session = connection.sessions().get();

        @Override
        public void open() throws IOException {
            session.open(sink, Duration.ofMillis(reconnect.connectTimeoutMs()));
        }

        @Override
        public void readNext() throws IOException {
            session.readNext(sink);
        }

        @Override
        public void close() {
            session.close();
        }
    }

    @FunctionalInterface
    private interface SessionWrite {
        void write(ClientSession session) throws IOException;
    }
}
