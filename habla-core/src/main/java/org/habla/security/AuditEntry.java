package org.habla.security;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Instant;

/**
 * One line of the audit log: who tried what on which port, when, and whether it was accepted or why not.
 *
 * @param when     the wall-clock time
 * @param client   the authenticated client's name, or {@code anonymous}
 * @param address  the peer's {@code host:port} (for a bridge, its broker's)
 * @param socket   the socket's name (or {@code @status})
 * @param action   {@code write}, {@code take}, {@code release} or {@code auth}
 * @param input    the control input written (null for other actions)
 * @param value    the value as the client sent it ({@code {"bytes":N}} for a binary block); null for other actions
 * @param accepted whether it was done
 * @param why      why not (an error code and sentence); null when accepted
 */
public record AuditEntry(Instant when, String client, String address, String socket, String action, String input,
        JsonNode value, boolean accepted, String why) {

    /** The longest value text an entry keeps; a longer one is cut and marked. */
    public static final int MAX_VALUE_CHARS = 4_096;

    public AuditEntry {
        if (value != null && value.toString().length() > MAX_VALUE_CHARS) {
            value = JsonNodeFactory.instance.objectNode()
                    .put("cut", value.toString().substring(0, MAX_VALUE_CHARS))
                    .put("chars", value.toString().length());
        }
    }

    /** The entry as its JSON line. */
    public ObjectNode json() {
        ObjectNode n = JsonNodeFactory.instance.objectNode()
                .put("time", when.toString())
                .put("client", client)
                .put("address", address)
                .put("socket", socket)
                .put("action", action);
        if (input != null) {
            n.put("input", input);
        }
        if (value != null) {
            n.set("value", value);
        }
        n.put("accepted", accepted);
        if (why != null) {
            n.put("why", why);
        }
        return n;
    }
}
