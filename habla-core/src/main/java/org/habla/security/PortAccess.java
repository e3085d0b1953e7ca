package org.habla.security;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Who may use one port: anyone ({@link #open}), or only clients that authenticate with a token from the
 * credentials file and hold a role on the port ({@link #authenticated}). Counts the port's authentications and
 * failures. Thread-safe.
 *
 * <pre>
 *   client  {"op":"auth","client":"mdb","token":"…"}
 *   port    admitted (name, role on this port)
 *           | auth_failed: unknown client or wrong token     (the caller waits FAILURE_DELAY_MS, then closes)
 *           | forbidden:   a known client without a role here
 * </pre>
 */
public final class PortAccess {

    /** How long a failed authentication waits before its error line, so guessing is slow. */
    public static final long FAILURE_DELAY_MS = 500;

    private final String key;
    private final Credentials credentials;
    private final AtomicLong admitted = new AtomicLong();
    private final AtomicLong failures = new AtomicLong();

    private PortAccess(String key, Credentials credentials) {
        this.key = Objects.requireNonNull(key, "key");
        this.credentials = credentials;
    }

    /** A port anyone may use: every client is {@link Principal#ANONYMOUS}. */
    public static PortAccess open(String key) {
        return new PortAccess(key, null);
    }

    /**
     * A port only named clients may use.
     *
     * @param key the port as roles name it: a socket's name or {@link Principal#STATUS}
     */
    public static PortAccess authenticated(String key, Credentials credentials) {
        return new PortAccess(key, Objects.requireNonNull(credentials, "credentials"));
    }

    /** Whether a client must authenticate before anything else. */
    public boolean required() {
        return credentials != null;
    }

    /** The port as roles name it. */
    public String key() {
        return key;
    }

    /** The outcome of one auth line. */
    public sealed interface Outcome {
    }

    /** Authenticated, with its role on this port. */
    public record Admitted(Principal principal, Role role) implements Outcome {
    }

    /** Refused: {@code code} is {@code auth_failed} or {@code forbidden}; {@code client} is the name it gave. */
    public record Refused(String code, String message, String client) implements Outcome {
    }

    /** Checks an auth line ({@code {"op":"auth","client":NAME,"token":TOKEN}}); counts a failure. */
    public Outcome authenticate(JsonNode line) {
        if (credentials == null) {
            return new Admitted(Principal.ANONYMOUS, Principal.ANONYMOUS.roleOn(key).orElse(Role.READ));
        }
        JsonNode name = line.get("client");
        JsonNode token = line.get("token");
        String given = name != null && name.isTextual() ? name.asText() : null;
        if (given == null || token == null || !token.isTextual()) {
            failures.incrementAndGet();
            return new Refused("auth_failed", "an auth line needs \"client\" and \"token\" strings: "
                    + "{\"op\":\"auth\",\"client\":NAME,\"token\":TOKEN}", Principal.ANONYMOUS_NAME);
        }
        var principal = credentials.verify(given, token.asText());
        if (principal.isEmpty()) {
            failures.incrementAndGet();
            return new Refused("auth_failed", "client '" + clip(given) + "' is unknown or its token is wrong; "
                    + "the attempt is counted and audited", clip(given));
        }
        var role = principal.get().roleOn(key);
        if (role.isEmpty()) {
            failures.incrementAndGet();
            return new Refused("forbidden", "client '" + given + "' has no role on " + describe()
                    + " (roles are given in the credentials file)", given);
        }
        admitted.incrementAndGet();
        return new Admitted(principal.get(), role.get());
    }

    /** Failed authentications so far. */
    public long failures() {
        return failures.get();
    }

    /** Successful authentications so far. */
    public long admittedTotal() {
        return admitted.get();
    }

    /** Adds {@code auth} ("required" or "off") and, when required, the counts to a port's figures. */
    public void putStats(ObjectNode stats) {
        stats.put("auth", required() ? "required" : "off");
        if (required()) {
            stats.put("authenticated", admitted.get()).put("authFailures", failures.get());
        }
    }

    private String describe() {
        return key.equals(Principal.STATUS) ? "the status endpoint" : "socket '" + key + "'";
    }

    /** A name as a prober gave it, short enough for a log line. */
    private static String clip(String s) {
        String printable = s.replaceAll("[^\\x20-\\x7e]", "?");
        return printable.length() <= 64 ? printable : printable.substring(0, 64) + "…";
    }
}
