package org.habla.config;

/**
 * A method's control socket.
 *
 * @param name the socket's name in the control contract (defaults to the method id)
 * @param bind the address to listen on (defaults to 127.0.0.1)
 * @param port the TCP port
 */
public record Expose(String name, String bind, int port) {
}
