package org.habla.graph;

import java.util.Objects;

/**
 * What a connection made of one command: written, not written because the connection is down, or refused with the
 * session's reason (a device that is offline, a value the protocol cannot encode).
 *
 * @param written whether the command went out
 * @param refusal why the session refused it; null when it was written or the connection is down
 */
record CommandResult(boolean written, String refusal) {

    static final CommandResult WRITTEN = new CommandResult(true, null);
    static final CommandResult DOWN = new CommandResult(false, null);

    static CommandResult refused(String why) {
        return new CommandResult(false, Objects.requireNonNull(why, "why"));
    }
}
