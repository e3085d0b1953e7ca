package org.habla.config;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.habla.driver.InterfaceAddress;
import org.habla.security.Credentials;
import org.habla.security.CredentialsFile;
import org.habla.security.Tls;

/**
 * Reads {@code "security"} and checks the policy on every port: a port bound beyond loopback must require
 * authentication unless {@code security.insecure} says otherwise, and a TLS socket needs a certificate. Files
 * are taken from the config's folder; the credentials file is read and checked here, so {@code habla check}
 * reports its problems (never its secrets) at {@code $.security.credentials}.
 */
final class SecurityReader {

    static final Set<String> SECURITY_KEYS =
            Set.of("credentials", "auditLog", "insecure", "loopback", "tls", "workerTrust");
    static final Set<String> TLS_KEYS = Set.of("certificate", "key");
    /** The audit log's file, beside the config, when there are credentials and {@code auditLog} is not given. */
    static final String DEFAULT_AUDIT_LOG = "habla-audit.log";

    private final ConfigErrors errors;
    private final Path baseDir;

    SecurityReader(ConfigErrors errors, Path baseDir) {
        this.errors = errors;
        this.baseDir = baseDir;
    }

    SecurityConfig read(Optional<CheckedObject> node, Set<String> sockets) {
        if (node.isEmpty()) {
            return SecurityConfig.DEFAULTS;
        }
        CheckedObject o = node.get();
        o.allowOnly(SECURITY_KEYS);
        Path credentialsFile = o.optionalString("credentials").map(this::file).orElse(null);
        Credentials credentials = null;
        if (credentialsFile != null) {
            try {
                credentials = CredentialsFile.read(credentialsFile, sockets);
            } catch (CredentialsFile.Invalid e) {
                for (String problem : e.problems()) {
                    errors.add(o.path().field("credentials"), credentialsFile.getFileName() + " " + problem);
                }
            }
        }
        Path auditLog = o.optionalString("auditLog").map(this::file)
                .orElse(credentialsFile == null ? null : baseDir.resolve(DEFAULT_AUDIT_LOG));
        boolean insecure = o.bool("insecure", false);
        String loopback = o.optionalString("loopback").orElse("open");
        if (!loopback.equals("open") && !loopback.equals("authenticated")) {
            errors.add(o.path().field("loopback"), "must be \"open\" or \"authenticated\", was \"" + loopback + "\"");
        }
        if (loopback.equals("authenticated") && credentialsFile == null) {
            errors.add(o.path().field("loopback"), "\"authenticated\" needs security.credentials");
        }
        Path certificate = null;
        Path key = null;
        Optional<CheckedObject> tls = o.object("tls");
        if (tls.isPresent()) {
            CheckedObject t = tls.get();
            t.allowOnly(TLS_KEYS);
            certificate = t.requiredString("certificate").map(this::file).orElse(null);
            key = t.requiredString("key").map(this::file).orElse(null);
            if (certificate != null && key != null) {
                try {
                    Tls.server(certificate, key);
                } catch (IOException e) {
                    errors.add(t.path(), e.getMessage());
                }
            }
        }
        Path workerTrust = o.optionalString("workerTrust").map(this::file).orElse(null);
        if (workerTrust != null) {
            try {
                Tls.client(workerTrust);
            } catch (IOException e) {
                errors.add(o.path().field("workerTrust"), e.getMessage());
            }
        }
        return new SecurityConfig(credentialsFile, credentials, auditLog, insecure, loopback.equals("authenticated"),
                certificate, key, workerTrust);
    }

    /**
     * The policy: every socket and the status endpoint bound beyond loopback require authentication unless
     * {@code security.insecure}; the monitor, which cannot authenticate, stays on loopback unless
     * {@code security.insecure}; a TLS socket needs {@code security.tls}; a method placed on a worker beyond
     * loopback needs the credentials file's {@code workerSecret}, since such a worker always asks for it.
     */
    void checkPolicy(SecurityConfig security, StatusConfig status, List<MethodEntry> methods) {
        for (MethodEntry m : methods) {
            m.expose().ifPresent(x -> {
                JsonPath at = m.path().field("expose");
                if (!SecurityConfig.isLoopback(x.bind()) && !security.authenticates(x.bind()) && !security.insecure()) {
                    errors.add(at.field("bind"), beyondLoopback("socket '" + x.name() + "'", x.bind()));
                }
                if (x.tls() && !security.hasTls()) {
                    errors.add(at.field("tls"), "a TLS socket needs security.tls with a certificate and its key "
                            + "(see docs/security.md)");
                }
            });
        }
        if (status.port() > 0 && !SecurityConfig.isLoopback(status.bind()) && !security.authenticates(status.bind())
                && !security.insecure()) {
            errors.add(JsonPath.ROOT.field("status").field("bind"), beyondLoopback("the status endpoint", status.bind()));
        }
        if (status.tls() && !security.hasTls()) {
            errors.add(JsonPath.ROOT.field("status").field("tls"), "a TLS status endpoint needs security.tls with a "
                    + "certificate and its key (see docs/security.md)");
        }
        boolean workerSecret = security.credentials() != null && security.credentials().workerSecret().isPresent();
        for (MethodEntry m : methods) {
            m.host().filter(h -> !workerSecret && !SecurityConfig.isLoopback(InterfaceAddress.parse(h).host()))
                    .ifPresent(h -> errors.add(m.path().field("host"), "worker " + h + " is beyond loopback, where a "
                            + "worker requires the shared secret (habla worker refuses to listen there without "
                            + "--secret-file): give \"workerSecret\" in the credentials file (security.credentials; "
                            + "see docs/security.md)"));
        }
        if (status.monitorPort() > 0 && !SecurityConfig.isLoopback(status.monitorBind()) && !security.insecure()) {
            errors.add(JsonPath.ROOT.field("status").field("monitorBind"), "the monitor has no authentication, so it "
                    + "may not listen on " + status.monitorBind() + " (beyond loopback) unless security.insecure is true");
        }
    }

    private static String beyondLoopback(String what, String bind) {
        return what + " binds " + bind + ", beyond loopback, without authentication: anyone on that network could "
                + "read it and drive the robot. Add security.credentials (docs/security.md), bind 127.0.0.1, or set "
                + "security.insecure to true to accept that";
    }

    private Path file(String given) {
        return baseDir.resolve(given).normalize();
    }
}
