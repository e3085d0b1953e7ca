package org.habla.net;

/**
 * A method's control socket.
 *
 * @param name the socket's name in the control contract (defaults to the method id)
 * @param bind the address to listen on (defaults to 127.0.0.1)
 * @param port the TCP port
 * @param tls  whether the socket speaks TLS, with the certificate of {@code security.tls}
 */
public record Expose(String name, String bind, int port, boolean tls) {

    /** A plain TCP socket. */
    public Expose(String name, String bind, int port) {
        this(name, bind, port, false);
    }
}
