package org.habla.security;

import java.util.Locale;
import java.util.Optional;

/**
 * What an authenticated client may do on one port: {@link #READ} its samples, {@code latest} and the status
 * endpoint's snapshot; {@link #COMMAND} all of that and write values to its control inputs (take and release
 * control too).
 */
public enum Role {
    READ,
    COMMAND;

    /** Whether this role covers {@code needed}: command covers read. */
    public boolean covers(Role needed) {
        return compareTo(needed) >= 0;
    }

    /** The name a credentials file uses: {@code read} or {@code command}. */
    public String fileName() {
        return name().toLowerCase(Locale.ROOT);
    }

    static Optional<Role> fromFile(String name) {
        for (Role r : values()) {
            if (r.fileName().equals(name)) {
                return Optional.of(r);
            }
        }
        return Optional.empty();
    }
}
