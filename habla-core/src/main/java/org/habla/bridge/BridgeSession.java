package org.habla.bridge;

import java.io.IOException;
import java.time.Duration;

/**
 * One connection of a bridge to where it carries the exposed methods (an MQTT broker), for the life of that
 * connection. The engine keeps it up as it keeps every link: it opens a session, reads it until it is lost, closes
 * it, waits with the bridge's {@code reconnect} back-off (shortest again once a session has been up, and after a
 * refused connect) and opens a fresh one; the status shows its connects, failures and last error.
 *
 * <pre>
 *   engine:  open(timeout) ──▶ readNext() … readNext() ──IOException──▶ close() ──back-off──▶ open …
 *   stop:    goodbye() (if up) ──▶ close()
 * </pre>
 *
 * <p>Threading: {@link #open} and {@link #readNext} run on the link's thread; what arrives may be acted on there or
 * on the client library's own threads (the {@code mqtt} bridge's actions go through the control points' checks,
 * which any thread may call). {@link #close} may come from any thread and must end a {@link #readNext} in
 * progress.
 */
public interface BridgeSession {

    /**
     * Connects and announces the bridge (says it is online, publishes what a new subscriber needs, subscribes),
     * giving up after {@code timeout}. An {@link IOException} says why; a {@link java.net.ConnectException} whose
     * message says "refused" is a host that answered that nothing listens yet, tried again soon.
     */
    void open(Duration timeout) throws IOException;

    /**
     * Blocks while the connection is up (for the next message from the other side, acting on it, or until the
     * connection is lost); returning is fine, the engine calls again. An {@link IOException} says the connection is
     * lost.
     */
    void readNext() throws IOException;

    /** Says goodbye (offline) before the daemon stops; called once, while the session is up. */
    default void goodbye() {
    }

    /** Disconnects and releases what the session holds. From any thread, more than once; never throws. */
    void close();
}
