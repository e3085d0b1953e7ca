package org.habla.driver;

import java.util.Objects;
import java.util.Set;
import java.util.function.Supplier;

/**
 * One connection a driver keeps through a client library that opens its own transport (see {@link ClientSession}),
 * where a {@link Connection} is a plain TCP socket the engine opens.
 *
 * @param name            a short name for logs and the status ({@code "broker"})
 * @param commandChannels the command channels written through this connection
 * @param sessions        makes a fresh session for every (re)connection
 */
public record ClientConnection(String name, Set<String> commandChannels, Supplier<ClientSession> sessions) {

    public ClientConnection {
        Objects.requireNonNull(name, "name");
        commandChannels = Set.copyOf(commandChannels);
        Objects.requireNonNull(sessions, "sessions");
    }
}
