package org.habla.bridge;

import java.util.Set;

/**
 * Whether something carried by a bridge may write actions to an exposed method, by socket name. A bridge reads
 * every socket it publishes, but writes only where its command role allows it: exactly the sockets its config
 * lists for actions, which a credentials file, when the config has one, must grant it too (who may publish
 * actions on the broker is the broker's to say). Every action it takes or refuses goes to the
 * daemon's audit log through {@link #audit}.
 */
@FunctionalInterface
public interface CommandRole {

    /** A role that may write to no socket. */
    CommandRole NONE = socket -> false;

    boolean mayCommand(String socket);

    /**
     * Records an action the bridge took ({@code refusal} null) or refused, in the daemon's audit log; by default
     * nowhere.
     *
     * @param value the action as it came (the message's text)
     */
    default void audit(org.habla.net.ClientId who, String socket, String input, String value, String refusal) {
    }

    /** This role, with every action it sees audited in {@code log}. */
    default CommandRole auditedIn(org.habla.security.AuditLog log) {
        CommandRole self = this;
        return new CommandRole() {
            @Override
            public boolean mayCommand(String socket) {
                return self.mayCommand(socket);
            }

            @Override
            public void audit(org.habla.net.ClientId who, String socket, String input, String value, String refusal) {
                log.add(new org.habla.security.AuditEntry(java.time.Instant.now(), org.habla.net.ClientId.ANONYMOUS.equals(
                        who.client()) ? who.connection() : who.client(), who.address(), socket,
                        "write", input, com.fasterxml.jackson.databind.node.JsonNodeFactory.instance.textNode(value),
                        refusal == null, refusal));
            }
        };
    }

    /** The role that may write to exactly these sockets. */
    static CommandRole of(Set<String> sockets) {
        Set<String> allowed = Set.copyOf(sockets);
        return allowed::contains;
    }
}
