package org.habla.graph;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.time.Duration;
import org.habla.bridge.Bridge;
import org.habla.bridge.BridgeSession;
import org.habla.config.Reconnect;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Keeps a bridge's connection up with the engine's {@link ReconnectingLink}, as every robot, client-library and
 * worker link is kept: a fresh {@link BridgeSession} per attempt, the {@link BackOff} of the bridge's
 * {@code reconnect} between attempts (shortest again once a session has been up, and after a refused connect),
 * one log line per outage, and the counts the status shows.
 */
public final class BridgeLink {

    private static final Logger LOG = LoggerFactory.getLogger(BridgeLink.class);

    private final Bridge bridge;
    private final ReconnectingLink<Attempt> link;

    /** A link for {@code bridge}, already started (attached to the exposed methods); call {@link #start}. */
    public BridgeLink(String id, Bridge bridge, Reconnect reconnect) {
        this.bridge = bridge;
        Duration timeout = Duration.ofMillis(reconnect.connectTimeoutMs());
        this.link = new ReconnectingLink<>("habla-bridge-" + id, reconnect, () -> new Attempt(bridge.session(), timeout),
                new OutageLog(LOG, "bridge " + id), new ReconnectingLink.StateListener() { });
    }

    /** Starts connecting, on the link's own thread; returns at once. */
    public void start() {
        link.start();
    }

    /** Says goodbye if connected, closes the connection and stops reconnecting; then closes the bridge. */
    public void stop() {
        link.stop();
        bridge.close();
    }

    public boolean up() {
        return link.up();
    }

    /** The bridge's own figures with the link's: {@code connected}, {@code connects}, {@code failures}, {@code lastError}. */
    public ObjectNode status() {
        ObjectNode n = bridge.status();
        n.put("connected", link.up()).put("connects", link.connects()).put("failures", link.failures());
        if (!link.lastError().isEmpty()) {
            n.put("lastError", link.lastError());
        }
        return n;
    }

    /** The wait chooser of this link (tests observe the waits it chooses). */
    BackOff backOff() {
        return link.backOff();
    }

    /** One session of the bridge, for one attempt. */
    private record Attempt(BridgeSession session, Duration timeout) implements ReconnectingLink.Session {

        @Override
        public void open() throws IOException {
            session.open(timeout);
        }

        @Override
        public void readNext() throws IOException {
            session.readNext();
        }

        @Override
        public void goodbye() {
            session.goodbye();
        }

        @Override
        public void close() {
            session.close();
        }
    }
}
