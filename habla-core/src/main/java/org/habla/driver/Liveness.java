package org.habla.driver;

import java.time.Duration;
import java.util.Objects;

/**
 * How the engine tells that the peer of a connection is lost, as the driver knows it from its protocol. A
 * quiet peer is not a lost peer: a read time-out means something only on a stream the peer keeps sending.
 *
 * <ul>
 *   <li>{@link Periodic}: the peer sends without being asked — ARCOS's SIP every 100 ms, Tekkotsu's sensor
 *       servers, a PCM stream, an interface program answering HABLA's pings. Silence longer than
 *       {@code lostAfter} means the peer is lost; the engine closes the connection and reconnects.</li>
 *   <li>{@link Quiet}: the peer speaks only when it has something to say — a keyboard, a bumper, a door
 *       contact, a server that only takes commands. Silence is normal and never ends the link.</li>
 * </ul>
 *
 * Whatever the kind, every connection has TCP keep-alive (the interface's {@code reconnect.tcpKeepAlive*}
 * settings), so a host that vanishes without closing the connection — power cut, cable pulled, out of Wi-Fi
 * range — is detected in a few seconds, and the peer closing or resetting the connection ends it at once.
 */
public sealed interface Liveness {

    /** A peer that keeps sending: {@code lostAfter} of silence means it is lost. */
    static Liveness periodic(Duration lostAfter) {
        return new Periodic(lostAfter);
    }

    /** A peer for whom silence is normal. */
    static Liveness quiet() {
        return Quiet.INSTANCE;
    }

    /** The silence after which the engine declares the peer lost, or zero if silence never means that. */
    Duration silenceLimit();

    /** A peer that sends without being asked; silence longer than {@code lostAfter} means it is lost. */
    record Periodic(Duration lostAfter) implements Liveness {
        public Periodic {
            Objects.requireNonNull(lostAfter, "lostAfter");
            if (lostAfter.isNegative() || lostAfter.isZero()) {
                throw new IllegalArgumentException("lostAfter must be positive, was " + lostAfter);
            }
        }

        @Override
        public Duration silenceLimit() {
            return lostAfter;
        }

        @Override
        public String toString() {
            return "periodic: lost after " + lostAfter.toMillis() + " ms of silence";
        }
    }

    /** A peer that speaks only when it has something to say; only TCP tells that it is gone. */
    enum Quiet implements Liveness {
        INSTANCE;

        @Override
        public Duration silenceLimit() {
            return Duration.ZERO;
        }

        @Override
        public String toString() {
            return "quiet: silence is normal";
        }
    }
}
