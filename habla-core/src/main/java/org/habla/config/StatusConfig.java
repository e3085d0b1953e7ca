package org.habla.config;

/**
 * The status endpoint read by {@code habla status}, and the live monitor served beside it.
 *
 * @param bind        the address both listen on
 * @param port        the status endpoint's TCP port (0 turns it off)
 * @param monitorPort the port of the live monitor: a web page and the Foxglove WebSocket protocol (0: no monitor)
 * @param tls         whether the status endpoint speaks TLS, with the certificate of {@code security.tls}
 */
public record StatusConfig(String bind, int port, int monitorPort, boolean tls) {

    public static final StatusConfig DEFAULTS = new StatusConfig("127.0.0.1", 7099, 0, false);

    /** The status endpoint over plain TCP, and the monitor. */
    public StatusConfig(String bind, int port, int monitorPort) {
        this(bind, port, monitorPort, false);
    }

    /** The status endpoint without a monitor. */
    public StatusConfig(String bind, int port) {
        this(bind, port, 0);
    }
}
