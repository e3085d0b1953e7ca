package org.habla.daemon;

import java.io.IOException;
import org.habla.net.Expose;
import org.habla.config.HablaConfig;
import org.habla.config.SecurityConfig;
import org.habla.security.AuditLog;
import org.habla.security.LoginThrottle;
import org.habla.security.PortAccess;
import org.habla.security.PortSecurity;
import org.habla.security.Principal;
import org.habla.security.Tls;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * How a daemon guards each of its ports, from the config's {@code security}: who may use each socket and the
 * status endpoint, the one audit log every command and refusal goes to, the one {@link LoginThrottle} that limits
 * each address's failed logins over all the ports, and the TLS of the sockets that ask for it. Warns, at
 * every start, of each port an {@code insecure} config leaves open beyond loopback.
 */
final class PortGuards implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(PortGuards.class);

    private final SecurityConfig security;
    private final AuditLog audit;
    private final Tls tls;
    /** The failed logins each address may make, over every port of the daemon together. */
    private final LoginThrottle throttle = new LoginThrottle();

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
        return new PortSecurity(access(expose.name(), expose.bind()), audit, expose.tls() ? tls : null);
    }

    /** The guard of the status endpoint: who may read it, the audit log, its TLS. */
    PortSecurity status(org.habla.config.StatusConfig status) {
        return new PortSecurity(access(Principal.STATUS, status.bind()), audit, status.tls() ? tls : null);
    }

    private PortAccess access(String key, String bind) {
        return security.authenticates(bind) ? PortAccess.authenticated(key, security.credentials(), throttle)
                : PortAccess.open(key);
    }

    AuditLog audit() {
        return audit;
    }

    private void warnOfOpenPorts(HablaConfig config) {
        insecurePorts(config).forEach(w -> LOG.warn("INSECURE: {}", w));
        tokensInClear(config).forEach(w -> LOG.warn("{}", w));
    }

    /** One sentence per port beyond loopback that authenticates over plain TCP: its tokens cross the network in clear. */
    static java.util.List<String> tokensInClear(HablaConfig config) {
        SecurityConfig security = config.security();
        java.util.List<String> clear = new java.util.ArrayList<>();
        config.methods().forEach(m -> m.expose().ifPresent(x -> {
            if (!SecurityConfig.isLoopback(x.bind()) && security.authenticates(x.bind()) && !x.tls()) {
                clear.add("socket '" + x.name() + "' on " + x.bind() + ":" + x.port() + " authenticates over plain "
                        + "TCP: its clients' tokens cross the network in clear (\"tls\": true encrypts them)");
            }
        }));
        var st = config.status();
        if (st.port() > 0 && !SecurityConfig.isLoopback(st.bind()) && security.authenticates(st.bind()) && !st.tls()) {
            clear.add("the status endpoint on " + st.bind() + ":" + st.port() + " authenticates over plain TCP: its "
                    + "clients' tokens cross the network in clear (\"tls\": true in status encrypts them)");
        }
        return clear;
    }

    /**
     * One sentence per port an {@code insecure} config leaves open beyond loopback: each is logged as a warning
     * at every start.
     */
    static java.util.List<String> insecurePorts(HablaConfig config) {
        SecurityConfig security = config.security();
        java.util.List<String> open = new java.util.ArrayList<>();
        if (!security.insecure()) {
            return open;
        }
        config.methods().forEach(m -> m.expose().ifPresent(x -> {
            if (!SecurityConfig.isLoopback(x.bind()) && !security.authenticates(x.bind())) {
                open.add("socket '" + x.name() + "' listens on " + x.bind() + ":" + x.port() + " without "
                        + "authentication (security.insecure is true): anyone on that network can read it and drive "
                        + "the robot");
            }
        }));
        var st = config.status();
        if (st.port() > 0 && !SecurityConfig.isLoopback(st.bind()) && !security.authenticates(st.bind())) {
            open.add("the status endpoint listens on " + st.bind() + ":" + st.port() + " without authentication "
                    + "(security.insecure is true)");
        }
        if (st.monitorPort() > 0 && !SecurityConfig.isLoopback(st.monitorBind())) {
            open.add("the monitor listens on " + st.monitorBind() + ":" + st.monitorPort() + " and has no authentication "
                    + "(security.insecure is true)");
        }
        return open;
    }

    @Override
    public void close() {
        audit.close();
    }
}
