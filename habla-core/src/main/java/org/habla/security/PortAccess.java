package org.habla.security;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Who may use one port: anyone ({@link #open}), or only clients that authenticate with a token from the
 * credentials file and hold a role on the port ({@link #authenticated}). Failed logins are limited per source
 * address by a {@link LoginThrottle} the daemon's ports share. Counts the port's authentications and failures.
 * Thread-safe.
 *
 * <pre>
 *   client  {"op":"auth","client":"mdb","token":"…"}
 *   port    admitted (name, role on this port)
 *           | auth_failed:    unknown client, wrong token, or not two strings   (the caller waits FAILURE_DELAY_MS, then closes)
 *           | auth_throttled: the address is out of tries; nothing was checked   (closed at once)
 *           | forbidden:      a known client without a role here
 * </pre>
 */
public final class PortAccess {

    /** How long a failed authentication waits before its error line, so guessing is slow. */
    public static final long FAILURE_DELAY_MS = 500;

    private final String key;
    private final Credentials credentials;
    private final LoginThrottle throttle;
    private final AtomicLong admitted = new AtomicLong();
    private final AtomicLong failures = new AtomicLong();
    private final AtomicLong throttled = new AtomicLong();

    private PortAccess(String key, Credentials credentials, LoginThrottle throttle) {
        this.key = Objects.requireNonNull(key, "key");
        this.credentials = credentials;
        this.throttle = throttle;
    }

    /** A port anyone may use: every client is {@link Principal#ANONYMOUS}. */
    public static PortAccess open(String key) {
        return new PortAccess(key, null, null);
    }

    /** A port only named clients may use, with a throttle of its own (a port alone, tests). */
    public static PortAccess authenticated(String key, Credentials credentials) {
        return authenticated(key, credentials, new LoginThrottle());
    }

    /**
     * A port only named clients may use.
     *
     * @param key      the port as roles name it: a socket's name or {@link Principal#STATUS}
     * @param throttle the failed logins each address may make, shared by the daemon's ports
     */
    public static PortAccess authenticated(String key, Credentials credentials, LoginThrottle throttle) {
        return new PortAccess(key, Objects.requireNonNull(credentials, "credentials"),
                Objects.requireNonNull(throttle, "throttle"));
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

    /**
     * Refused: {@code code} is {@code auth_failed}, {@code auth_throttled} or {@code forbidden}; {@code client} is
     * the name it gave.
     */
    public record Refused(String code, String message, String client) implements Outcome {
        /** Whether the answer waits {@link #FAILURE_DELAY_MS}: only for a checked, failed guess. */
        public boolean delayed() {
            return code.equals("auth_failed");
        }
    }

    /** Who a client of an open port is: anonymous, with the role anonymous clients have. */
    public Admitted anonymous() {
        return new Admitted(Principal.ANONYMOUS, Principal.ANONYMOUS.roleOn(key).orElse(Role.READ));
    }

    /**
     * Checks an auth line ({@code {"op":"auth","client":NAME,"token":TOKEN}}) that came from {@code host}, unless
     * that address is out of tries ({@link LoginThrottle}); counts every failure, checked or not.
     */
    public Outcome authenticate(JsonNode line, String host) {
        if (credentials == null) {
            return anonymous();
        }
        JsonNode name = line.get("client");
        String given = name != null && name.isTextual() ? clip(name.asText()) : Principal.ANONYMOUS_NAME;
        long waitMs = throttle.take(host);
        if (waitMs > 0) {
            failures.incrementAndGet();
            throttled.incrementAndGet();
            return new Refused("auth_throttled", "too many failed logins from " + host + " (at most "
                    + LoginThrottle.BURST + " at once, then one every " + LoginThrottle.REFILL_MS + " ms): not checked;"
                    + " try again in " + waitMs + " ms. The attempt is counted and audited", given);
        }
        Outcome outcome = check(line);
        if (outcome instanceof Refused r && r.delayed()) {
            failures.incrementAndGet();
        } else {
            throttle.giveBack(host); // not a wrong guess: the token was right, or there was none to check
            if (outcome instanceof Refused) {
                failures.incrementAndGet();
            } else {
                admitted.incrementAndGet();
            }
        }
        return outcome;
    }

    private Outcome check(JsonNode line) {
        JsonNode name = line.get("client");
        JsonNode token = line.get("token");
        String given = name != null && name.isTextual() ? name.asText() : null;
        if (given == null || token == null || !token.isTextual()) {
            return new Refused("auth_failed", "an auth line needs \"client\" and \"token\" strings: "
                    + "{\"op\":\"auth\",\"client\":NAME,\"token\":TOKEN}; the attempt is counted and audited",
                    given == null ? Principal.ANONYMOUS_NAME : clip(given));
        }
        var principal = credentials.verify(given, token.asText());
        if (principal.isEmpty()) {
            return new Refused("auth_failed", "client '" + clip(given) + "' is unknown or its token is wrong; "
                    + "the attempt is counted and audited", clip(given));
        }
        var role = principal.get().roleOn(key);
        if (role.isEmpty()) {
            return new Refused("forbidden", "client '" + given + "' has no role on " + describe()
                    + " (roles are given in the credentials file)", given);
        }
        return new Admitted(principal.get(), role.get());
    }

    /** Failed authentications so far. */
    public long failures() {
        return failures.get();
    }

    /** Attempts refused unchecked, their address out of tries, so far (counted in {@link #failures} too). */
    public long throttledTotal() {
        return throttled.get();
    }

    /** Successful authentications so far. */
    public long admittedTotal() {
        return admitted.get();
    }

    /** Adds {@code auth} ("required" or "off") and, when required, the counts to a port's figures. */
    public void putStats(ObjectNode stats) {
        stats.put("auth", required() ? "required" : "off");
        if (required()) {
            stats.put("authenticated", admitted.get()).put("authFailures", failures.get())
                    .put("authThrottled", throttled.get());
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
