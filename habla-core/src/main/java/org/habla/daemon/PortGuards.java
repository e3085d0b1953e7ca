package org.habla.daemon;

import java.io.IOException;
import org.habla.config.Expose;
import org.habla.config.HablaConfig;
import org.habla.config.SecurityConfig;
import org.habla.security.AuditLog;
import org.habla.security.PortAccess;
import org.habla.security.PortSecurity;
import org.habla.security.Principal;
import org.habla.security.Tls;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * How a daemon guards each of its ports, from the config's {@code security}: who may use each socket and the
 * status endpoint, the one audit log every command goes to, and the TLS of the sockets that ask for it. Warns, at
 * every start, of each port an {@code insecure} config leaves open beyond loopback.
 */
final class PortGuards implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(PortGuards.class);

    private final SecurityConfig security;
    private final AuditLog audit;
    private final Tls tls;

    private PortGuards(SecurityConfig security, AuditLog audit, Tls tls) {
        this.security = security;
        this.audit = audit;
        this.tls = tls;
    }

    static PortGuards of(HablaConfig config) throws IOException {
        SecurityConfig s = config.security();
        AuditLog audit = s.auditLog() == null ? AuditLog.withoutFile() : AuditLog.open(s.auditLog());
        Tls tls = s.hasTls() ? Tls.server(s.tlsCertificate(), s.tlsKey()) : null;
        PortGuards guards = new PortGuards(s, audit, tls);
        guards.warnOfOpenPorts(config);
        if (audit.file() != null) {
            LOG.info("audit log: {}", audit.file());
        }
        return guards;
    }

    /** The guard of a control socket. */
    PortSecurity socket(Expose expose) {
        PortAccess access = security.authenticates(expose.bind())
                ? PortAccess.authenticated(expose.name(), security.credentials())
                : PortAccess.open(expose.name());
        return new PortSecurity(access, audit, expose.tls() ? tls : null);
    }

    /** Who may read the status endpoint bound to {@code bind}. */
    PortAccess status(String bind) {
        return security.authenticates(bind) ? PortAccess.authenticated(Principal.STATUS, security.credentials())
                : PortAccess.open(Principal.STATUS);
    }

    AuditLog audit() {
        return audit;
    }

    private void warnOfOpenPorts(HablaConfig config) {
        if (!security.insecure()) {
            return;
        }
        config.methods().forEach(m -> m.expose().ifPresent(x -> {
            if (!SecurityConfig.isLoopback(x.bind()) && !security.authenticates(x.bind())) {
                LOG.warn("INSECURE: socket '{}' listens on {}:{} without authentication (security.insecure is true):"
                        + " anyone on that network can read it and drive the robot", x.name(), x.bind(), x.port());
            }
        }));
        var st = config.status();
        if (st.port() > 0 && !SecurityConfig.isLoopback(st.bind()) && !security.authenticates(st.bind())) {
            LOG.warn("INSECURE: the status endpoint listens on {}:{} without authentication (security.insecure is "
                    + "true)", st.bind(), st.port());
        }
        if (st.monitorPort() > 0 && !SecurityConfig.isLoopback(st.bind())) {
            LOG.warn("INSECURE: the monitor listens on {}:{} and has no authentication (security.insecure is true)",
                    st.bind(), st.monitorPort());
        }
    }

    @Override
    public void close() {
        audit.close();
    }
}
