package org.habla.bridge;

import java.util.Set;

/**
 * Whether something carried by a bridge may write actions to an exposed method, by socket name. A bridge reads
 * every socket it publishes, but writes only where its command role allows it; until the daemon has roles of its
 * own, a bridge's command role is exactly the sockets its config lists for actions.
 */
@FunctionalInterface
public interface CommandRole {

    /** A role that may write to no socket. */
    CommandRole NONE = socket -> false;

    boolean mayCommand(String socket);

    /** The role that may write to exactly these sockets. */
    static CommandRole of(Set<String> sockets) {
        Set<String> allowed = Set.copyOf(sockets);
        return allowed::contains;
    }
}
