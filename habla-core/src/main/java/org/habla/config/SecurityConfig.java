package org.habla.config;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.file.Path;
import org.habla.security.Credentials;

/**
 * Who may use the daemon's ports and how they are guarded ({@code "security"} in a config; see
 * {@code docs/security.md}).
 *
 * @param credentialsFile the credentials file (clients, tokens, roles, the worker secret), or null for none
 * @param credentials     what it holds, read and checked with the config; null without a file
 * @param auditLog        the append-only audit log, or null for none (with credentials it defaults to
 *                        {@code habla-audit.log} beside the config)
 * @param insecure        whether a port may be bound beyond loopback without authentication (warned at every start)
 * @param authOnLoopback  whether ports bound to loopback require authentication too (when there are credentials)
 * @param tlsCertificate  the PEM certificate (chain) of TLS sockets, or null
 * @param tlsKey          its unencrypted PKCS#8 PEM key, or null
 * @param workerTrust     the PEM certificate workers must present: the worker link speaks TLS; null for plain TCP
 */
public record SecurityConfig(Path credentialsFile, Credentials credentials, Path auditLog, boolean insecure,
        boolean authOnLoopback, Path tlsCertificate, Path tlsKey, Path workerTrust) {

    /** No credentials, no audit log, loopback only, plain TCP. */
    public static final SecurityConfig DEFAULTS = new SecurityConfig(null, null, null, false, false, null, null, null);

    /** Whether a port bound to {@code bind} requires authentication. */
    public boolean authenticates(String bind) {
        return credentials != null && (authOnLoopback || !isLoopback(bind));
    }

    /** How the daemon reaches its workers: the credentials file's worker secret, TLS when {@code workerTrust}. */
    public org.habla.security.WorkerLink workerLink() {
        var secret = credentials == null ? null : credentials.workerSecret().orElse(null);
        try {
            var tls = workerTrust == null ? null : org.habla.security.Tls.client(workerTrust);
            return new org.habla.security.WorkerLink(secret, tls);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** Whether the config has a TLS certificate for sockets. */
    public boolean hasTls() {
        return tlsCertificate != null;
    }

    /** Whether {@code bind} is a loopback address (a name that does not resolve is taken as beyond loopback). */
    public static boolean isLoopback(String bind) {
        if (bind == null || bind.isBlank()) {
            return true; // the default bind address is 127.0.0.1
        }
        try {
            return InetAddress.getByName(bind).isLoopbackAddress();
        } catch (UnknownHostException e) {
            return false;
        }
    }
}
