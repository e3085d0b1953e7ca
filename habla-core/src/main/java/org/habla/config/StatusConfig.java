package org.habla.config;

/**
 * The status endpoint read by {@code habla status}, and the live monitor served beside it.
 *
 * @param bind        the address the status endpoint listens on
 * @param port        the status endpoint's TCP port (0 turns it off)
 * @param monitorPort the port of the live monitor: a web page and the Foxglove WebSocket protocol (0: no monitor)
 * @param tls         whether the status endpoint speaks TLS, with the certificate of {@code security.tls}
 * @param monitorBind the address the monitor listens on: loopback unless asked, since it has no authentication
 */
public record StatusConfig(String bind, int port, int monitorPort, boolean tls, String monitorBind) {

    public static final StatusConfig DEFAULTS = new StatusConfig("127.0.0.1", 7099, 0, false, "127.0.0.1");

    /** The status endpoint and the monitor, the monitor on loopback. */
    public StatusConfig(String bind, int port, int monitorPort, boolean tls) {
        this(bind, port, monitorPort, tls, DEFAULTS.monitorBind());
    }

    /** The status endpoint over plain TCP, and the monitor on loopback. */
    public StatusConfig(String bind, int port, int monitorPort) {
        this(bind, port, monitorPort, false);
    }

    /** The status endpoint without a monitor. */
    public StatusConfig(String bind, int port) {
        this(bind, port, 0);
    }
}
