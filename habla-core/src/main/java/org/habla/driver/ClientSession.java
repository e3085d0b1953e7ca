package org.habla.driver;

import java.io.IOException;
import java.time.Duration;
import org.habla.sample.Payload;

/**
 * The protocol spoken over one connection that a client library opens itself (an MQTT client with its own
 * TLS and keep-alive, say), for the life of that connection. It is the counterpart of {@link LinkSession} for
 * transports the engine does not open as a plain TCP socket: the engine still decides when to connect, waits
 * between attempts with its back-off, marks the interface down and stale while the connection is lost, and
 * serialises writes; the session only opens, decodes and encodes.
 *
 * <pre>
 *   engine:   open(sink, timeout) ──▶ readNext(sink) … readNext(sink) ──IOException──▶ close() ──back-off──▶ open …
 *   any thread, under the link's write lock:  write(channel, value)   stopMotion()
 * </pre>
 *
 * <p>Threading: {@link #open} and {@link #readNext} run on the link's reader thread, and every reading reaches
 * the sink from there (a library that calls back on threads of its own hands its messages to that thread,
 * through a bounded queue); the write methods run under the link's write lock, from any thread; {@link #close}
 * may come from any thread and must end a {@link #readNext} in progress.
 */
public interface ClientSession {

    /**
     * Connects and runs the opening exchange (log in, subscribe), giving up after {@code timeout}. An
     * {@link IOException} says why it failed, and the engine tries again after its back-off.
     */
    void open(ReadingSink sink, Duration timeout) throws IOException;

    /**
     * Blocks for the next unit of input and decodes it into {@code sink}; input that cannot be decoded is
     * reported through {@link ReadingSink#malformed} and skipped. An {@link IOException} says the connection is
     * lost (the engine marks it down, closes the session and reconnects).
     */
    void readNext(ReadingSink sink) throws IOException;

    /**
     * Sends a command on one of this connection's command channels. A command that cannot be encoded or sent to
     * its device now is refused with an {@link IllegalArgumentException} before anything is sent: the engine drops
     * and counts it and the link stays up. An {@link IOException} ends the connection.
     */
    default void write(String channel, Payload command) throws IOException {
        throw new IOException("this connection carries no command channel '" + channel + "'");
    }

    /** Sends what stops every motion this connection commands. */
    default void stopMotion() throws IOException {
    }

    /** Says goodbye if connected and releases everything the session holds. Safe to call twice, from any thread. */
    void close();
}
