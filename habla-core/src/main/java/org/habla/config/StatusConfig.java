package org.habla.config;

/**
 * The status endpoint read by {@code habla status}.
 *
 * @param bind the address to listen on
 * @param port the TCP port (0 turns the endpoint off)
 */
public record StatusConfig(String bind, int port) {

    public static final StatusConfig DEFAULTS = new StatusConfig("127.0.0.1", 7099);
}
