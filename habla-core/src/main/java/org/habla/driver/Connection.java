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
 * @param optional         whether the interface is up without it: a connection that carries no data the robot
 *                         needs to stream (a menu server that only switches the others on). The engine still keeps
 *                         it connected and reports it in the {@code link} record.
 */
public record Connection(String name, int port, Set<String> commandChannels, Liveness liveness,
        Supplier<LinkSession> sessions, boolean optional) {

    public Connection {
        Objects.requireNonNull(name, "name");
        if (port < 1 || port > 65_535) {
            throw new IllegalArgumentException("port must be in 1..65535, was " + port);
        }
        commandChannels = Set.copyOf(commandChannels);
        Objects.requireNonNull(liveness, "liveness");
        Objects.requireNonNull(sessions, "sessions");
    }

    /** A connection the interface needs to be up. */
    public Connection(String name, int port, Set<String> commandChannels, Liveness liveness,
            Supplier<LinkSession> sessions) {
        this(name, port, commandChannels, liveness, sessions, false);
    }

    /** This connection, marked optional: the interface is up while it is down. */
    public Connection asOptional() {
        return new Connection(name, port, commandChannels, liveness, sessions, true);
    }
}
