package org.habla.config;

/**
 * How an interface link is re-established after it drops.
 *
 * @param initialMs       the first wait after a failure
 * @param maxMs           the longest wait (the wait doubles up to this)
 * @param connectTimeoutMs how long one connect and handshake may take
 * @param readTimeoutMs   silence on the link after which it is declared lost
 */
public record Reconnect(long initialMs, long maxMs, long connectTimeoutMs, long readTimeoutMs) {

    public static final Reconnect DEFAULTS = new Reconnect(200, 5_000, 3_000, 3_000);
}
