package org.habla.graph;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Set;
import org.habla.sample.Payload;

/**
 * One connection of an interface that the engine keeps alive, whatever carries it: a TCP socket the engine
 * opens ({@link ConnectionLink}) or a client library's own transport ({@link ClientLink}). What the interface
 * needs of it: its state, its command routes, and a way to write.
 */
interface Link {

    /** The driver's name for the connection ({@code "arcos"}, {@code "broker"}). */
    String connectionName();

    /** The command channels written through this connection. */
    Set<String> commandChannels();

    boolean up();

    /** Whether the interface is up without this connection (the driver marked it optional). */
    default boolean optional() {
        return false;
    }

    /** Why the last attempt or session failed; empty when none did. */
    String lastError();

    void start();

    /** Says goodbye if connected, closes and stops reconnecting. */
    void stop();

    /** Writes a command now, or says why not: the connection is down, or its session refused the command. */
    CommandResult command(String channel, Payload value);

    boolean stopMotion();

    ObjectNode status();
}
