package org.habla.driver;

import java.util.Objects;
import java.util.Set;
import java.util.function.Supplier;

/**
 * One TCP connection a driver keeps to the robot.
 *
 * @param name             a short name for logs and the status ({@code "arcos"}, {@code "worldstate"})
 * @param port             the TCP port on the interface's host
 * @param commandChannels  the command channels written through this connection
 * @param liveness         how the engine tells the peer is lost: a stream that stops, or only TCP for a quiet peer
 * @param sessions         makes a fresh session for every (re)connection
 */
public record Connection(String name, int port, Set<String> commandChannels, Liveness liveness,
        Supplier<LinkSession> sessions) {

    public Connection {
        Objects.requireNonNull(name, "name");
        if (port < 1 || port > 65_535) {
            throw new IllegalArgumentException("port must be in 1..65535, was " + port);
        }
        commandChannels = Set.copyOf(commandChannels);
        Objects.requireNonNull(liveness, "liveness");
        Objects.requireNonNull(sessions, "sessions");
    }
}
