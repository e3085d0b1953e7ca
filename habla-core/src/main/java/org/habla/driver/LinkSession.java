package org.habla.driver;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.time.Duration;
import java.util.Optional;
import org.habla.sample.Payload;

/**
 * The protocol spoken over one TCP connection to a robot, for the life of that connection.
 * The engine connects, reconnects with back-off, tells a lost peer (by the {@link Liveness} its
 * {@link Connection} declares, and TCP keep-alive) and serialises writes; the session only turns bytes into
 * readings and commands into bytes.
 *
 * <p>Threading: {@link #handshake} and {@link #readNext} run on the link's reader thread; the write
 * methods run under the link's write lock, from any thread. State shared between the two sides must
 * be safe for that.
 */
public interface LinkSession {

    /**
     * Runs the connection's opening exchange (e.g. SYNC0/1/2, OPEN, ENABLE). Reads time out after the
     * interface's {@code connectTimeoutMs}. A session that
     * carries a motion channel leaves the robot still: a robot that may remember the speeds of an earlier session
     * and resume them is stopped before anything is enabled (the Pioneer's STOP right after OPEN, zeros to the
     * Aibo's walk). A protocol whose robot stops by itself when the connection ends, as HABLA's interface
     * protocol asks of its programs, needs nothing here.
     */
    default void handshake(InputStream in, OutputStream out, ReadingSink sink) throws IOException {
    }

    /**
     * Blocks for the next unit of input (a packet, a frame, a line), decodes it into {@code sink}. On a periodic
     * connection a read times out after its silence limit and the engine declares the peer lost; on a quiet one
     * it waits as long as the peer is silent.
     * Input that cannot be decoded is reported through {@link ReadingSink#malformed} and skipped;
     * an {@link IOException} ends the connection (and the engine reconnects).
     */
    void readNext(InputStream in, ReadingSink sink) throws IOException;

    /**
     * Encodes a command for one of this connection's command channels. A command that cannot be encoded
     * (a wrong length, NaN) is refused with an {@link IllegalArgumentException} before any byte is written:
     * the engine drops and counts it and the link stays up. An {@link IOException} ends the connection.
     */
    default void write(String channel, Payload command, OutputStream out) throws IOException {
        throw new IOException("this connection carries no command channel '" + channel + "'");
    }

    /** How often the connection needs {@link #keepAlive}, if at all. */
    default Optional<Duration> keepAlivePeriod() {
        return Optional.empty();
    }

    /** Writes whatever keeps the robot's watchdog content (e.g. PULSE), or re-sends a standing command. */
    default void keepAlive(OutputStream out) throws IOException {
    }

    /** Writes what stops every motion this connection commands. */
    default void stopMotion(OutputStream out) throws IOException {
    }

    /** Writes the polite goodbye on shutdown (e.g. CLOSE). */
    default void goodbye(OutputStream out) throws IOException {
    }
}
