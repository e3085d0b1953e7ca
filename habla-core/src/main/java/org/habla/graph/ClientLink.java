package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.time.Duration;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
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
 * is lost, closes it, waits with the engine's {@link BackOff} and opens a fresh session. The wait starts again
 * from the shortest once a session has been up. Writes come from any thread and are serialised; a write while
 * the connection is down is refused, never queued, so a command is never applied late.
 */
final class ClientLink implements Link {

    private static final Logger LOG = LoggerFactory.getLogger(ClientLink.class);

    private final String name;
    private final ClientConnection connection;
    private final Reconnect reconnect;
    private final BackOff backOff;
    private final OutageLog outages;
    private final ReadingSink sink;
    private final Runnable onStateChange;
    private final ReentrantLock writeLock = new ReentrantLock();
    private final AtomicLong connects = new AtomicLong();
    private final AtomicLong failures = new AtomicLong();
    private volatile boolean running;
    private volatile boolean up;
    private volatile String lastError = "";
    private volatile ClientSession session;
    private Thread thread;

    ClientLink(String interfaceId, ClientConnection connection, Reconnect reconnect, ReadingSink sink,
            Runnable onStateChange) {
        this.name = interfaceId + "/" + connection.name();
        this.connection = connection;
        this.reconnect = reconnect;
        this.backOff = new BackOff(reconnect);
        this.outages = new OutageLog(LOG, "link " + name);
        this.sink = sink;
        this.onStateChange = onStateChange;
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
        return up;
    }

    @Override
    public String lastError() {
        return lastError;
    }

    @Override
    public void start() {
        running = true;
        thread = Thread.ofVirtual().name("habla-link-" + name).start(this::loop);
    }

    @Override
    public void stop() {
        running = false;
        ClientSession s = session;
        if (s != null) {
            s.close();
        }
        backOff.wake();
        if (thread != null) {
            try {
                thread.join(2_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private void loop() {
        while (running) {
            ClientSession s = connection.sessions().get();
            session = s;
            Exception failure;
            try {
                s.open(sink, Duration.ofMillis(reconnect.connectTimeoutMs()));
                connects.incrementAndGet();
                lastError = "";
                up = true;
                backOff.reset();
                outages.up();
                onStateChange.run();
                while (running) {
                    s.readNext(sink);
                }
                break;
            } catch (IOException | RuntimeException e) {
                failure = e;
                if (running) {
                    failures.incrementAndGet();
                    lastError = e.getMessage() == null ? e.toString() : e.getMessage();
                    outages.failed(lastError);
                }
            } finally {
                markDown(s);
            }
            if (running && !backOff.pause(failure, () -> running)) {
                running = false;
            }
        }
    }

    private void markDown(ClientSession s) {
        boolean was = up;
        writeLock.lock();
        try {
            up = false;
            session = null;
        } finally {
            writeLock.unlock();
        }
        s.close();
        if (was) {
            onStateChange.run();
        }
    }

    @Override
    public boolean command(String channel, Payload value) {
        return write("command " + channel, s -> s.write(channel, value));
    }

    @Override
    public boolean stopMotion() {
        return write("stop", ClientSession::stopMotion);
    }

    private boolean write(String what, SessionWrite action) {
        writeLock.lock();
        try {
            ClientSession s = session;
            if (!up || s == null) {
                return false;
            }
            action.write(s);
            return true;
        } catch (IllegalArgumentException e) {
            LOG.warn("link {}: {} refused: {}", name, what, e.getMessage());
            return false;
        } catch (IOException | RuntimeException e) {
            LOG.warn("link {}: {} failed, reconnecting: {}", name, what, e.toString());
            ClientSession s = session;
            if (s != null) {
                s.close();
            }
            return false;
        } finally {
            writeLock.unlock();
        }
    }

    @Override
    public ObjectNode status() {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("name", connection.name());
        n.put("up", up);
        n.put("connects", connects.get());
        n.put("failures", failures.get());
        if (!lastError.isEmpty()) {
            n.put("lastError", lastError);
        }
        return n;
    }

    @FunctionalInterface
    private interface SessionWrite {
        void write(ClientSession session) throws IOException;
    }
}
