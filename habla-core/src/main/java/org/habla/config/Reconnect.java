package org.habla.config;

/**
 * How a link notices that its peer is lost and how it is re-established.
 *
 * @param initialMs        the first wait after a failure (and the wait after a refused connect)
 * @param maxMs            the longest wait (the wait doubles up to this)
 * @param connectTimeoutMs how long one connect and handshake may take
 * @param readTimeoutMs    silence after which a connection whose peer keeps sending is declared lost, replacing
 *                         the driver's own limit; 0 keeps the driver's. Quiet connections ignore it.
 * @param tcpKeepAlive     the TCP keep-alive every connection has
 */
public record Reconnect(long initialMs, long maxMs, long connectTimeoutMs, long readTimeoutMs,
        TcpKeepAlive tcpKeepAlive) {

    public static final Reconnect DEFAULTS = new Reconnect(200, 5_000, 3_000, 0, TcpKeepAlive.DEFAULTS);

    /** With the default TCP keep-alive. */
    public Reconnect(long initialMs, long maxMs, long connectTimeoutMs, long readTimeoutMs) {
        this(initialMs, maxMs, connectTimeoutMs, readTimeoutMs, TcpKeepAlive.DEFAULTS);
    }

    /**
     * TCP keep-alive: after {@code idleS} seconds without a byte either way the system sends a probe, then one
     * every {@code intervalS}; after {@code count} unanswered probes the connection fails. A host that vanished
     * without closing is so detected in {@code idleS + count × intervalS} seconds (5 s by default), on a
     * connection that is otherwise quiet.
     */
    public record TcpKeepAlive(int idleS, int intervalS, int count) {

        public static final TcpKeepAlive DEFAULTS = new TcpKeepAlive(2, 1, 3);

        /** The longest silence of a vanished host before the connection fails, in seconds. */
        public int detectionS() {
            return idleS + count * intervalS;
        }
    }
}
