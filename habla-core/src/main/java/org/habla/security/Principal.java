package org.habla.security;

import java.util.Map;
import java.util.Optional;

/**
 * A client as the daemon knows it after authentication: its name and its role on each port, by socket name,
 * {@value #STATUS} for the status endpoint and {@value #ANY} for every socket not named.
 *
 * @param name  the client's name in the credentials file; {@value #ANONYMOUS_NAME} where authentication is off
 * @param roles its roles by port
 */
public record Principal(String name, Map<String, Role> roles) {

    /** The key of the status endpoint in a client's roles. */
    public static final String STATUS = "@status";
    /** The key that stands for every control socket a client's roles do not name. */
    public static final String ANY = "*";
    /** How the audit log and the commander's label name a client that did not authenticate. */
    public static final String ANONYMOUS_NAME = "anonymous";
    /** Anyone, on a port without authentication: may do everything the port offers. */
    public static final Principal ANONYMOUS = new Principal(ANONYMOUS_NAME, Map.of(ANY, Role.COMMAND,
            STATUS, Role.READ));

    public Principal {
        roles = Map.copyOf(roles);
    }

    /** Its role on the port {@code key} (a socket's name or {@link #STATUS}), if any. */
    public Optional<Role> roleOn(String key) {
        Role r = roles.get(key);
        if (r == null && !key.equals(STATUS)) {
            r = roles.get(ANY);
        }
        return Optional.ofNullable(r);
    }
}
