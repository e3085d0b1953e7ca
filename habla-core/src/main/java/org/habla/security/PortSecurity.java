package org.habla.security;

import java.util.Objects;

/**
 * How one port is guarded beyond its caps and deadlines: who may use it ({@link PortAccess}), where its
 * commands are audited ({@link AuditLog}), and whether it speaks TLS ({@link Tls}, null for plain TCP).
 */
public record PortSecurity(PortAccess access, AuditLog audit, Tls tls) {

    public PortSecurity {
        Objects.requireNonNull(access, "access");
        Objects.requireNonNull(audit, "audit");
    }

    /** Anyone may use the port, over plain TCP; commands reach no file. */
    public static PortSecurity open(String key) {
        return new PortSecurity(PortAccess.open(key), AuditLog.withoutFile(), null);
    }
}
