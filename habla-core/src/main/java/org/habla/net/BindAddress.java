package org.habla.net;

import java.io.IOException;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ProtocolFamily;
import java.net.StandardProtocolFamily;
import java.net.StandardSocketOptions;
import java.net.UnknownHostException;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;

/**
 * The address a server of the daemon listens on, exactly as a config or a command line names it. An IPv4 address
 * gets an IPv4 socket: {@code 0.0.0.0} is every IPv4 address of the computer and no IPv6 one. An IPv6 address gets
 * an IPv6 socket: {@code ::} is every address of both families where the kernel keeps IPv4 on IPv6 sockets (Linux's
 * default, {@code net.ipv6.bindv6only = 0}), {@code ::1} the IPv6 loopback only. (Java's own sockets would listen on
 * {@code ::} when asked for {@code 0.0.0.0}.) A name is resolved and listened on at its first address.
 *
 * @param text    the address as it was given, for messages
 * @param address what it resolved to
 */
public record BindAddress(String text, InetAddress address) {

    /** The address a server listens on when nothing is given. */
    public static final String DEFAULT = "127.0.0.1";

    /**
     * The address {@code bind} names; null or blank is {@link #DEFAULT}.
     *
     * @throws UnknownHostException when the name does not resolve
     */
    public static BindAddress of(String bind) throws UnknownHostException {
        String text = bind == null || bind.isBlank() ? DEFAULT : bind.strip();
        return new BindAddress(text, InetAddress.getByName(text));
    }

    /** The family of socket that listens on exactly this address. */
    public ProtocolFamily family() {
        return address instanceof Inet4Address ? StandardProtocolFamily.INET : StandardProtocolFamily.INET6;
    }

    /**
     * A server channel listening on {@code port} (0: any free port) of this address, with address reuse, in blocking
     * mode; its {@code socket()} accepts as a {@link java.net.ServerSocket} does.
     */
    public ServerSocketChannel listen(int port, int backlog) throws IOException {
        ServerSocketChannel channel = ServerSocketChannel.open(family());
        try {
            channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            channel.bind(new InetSocketAddress(address, port), backlog);
            return channel;
        } catch (IOException | RuntimeException e) {
            channel.close();
            throw e;
        }
    }

    /**
     * Binds {@code port} of this address with a socket that never listens, and lets it go: throws exactly when a
     * server could not have the port, while nobody can connect meanwhile.
     */
    public void probe(int port) throws IOException {
        try (SocketChannel probe = SocketChannel.open(family())) {
            probe.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            probe.bind(new InetSocketAddress(address, port));
        }
    }

    /**
     * Where a client on this computer reaches a server listening here: the loopback address of the family for a
     * wildcard, else this address.
     */
    public InetAddress local() throws UnknownHostException {
        if (!address.isAnyLocalAddress()) {
            return address;
        }
        return InetAddress.getByName(address instanceof Inet4Address ? "127.0.0.1" : "::1");
    }

    @Override
    public String toString() {
        return text;
    }
}
