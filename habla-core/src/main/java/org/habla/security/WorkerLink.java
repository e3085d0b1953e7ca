package org.habla.security;

import java.io.IOException;
import java.net.Socket;

/**
 * How a daemon reaches its workers: the secret it proves to them and asks them to prove ({@link WorkerSecret};
 * null when the daemon has none) and the TLS it speaks to them ({@link Tls} trusting the workers' certificate;
 * null for plain TCP).
 */
public record WorkerLink(WorkerSecret secret, Tls tls) {

    /** No secret, plain TCP: only for workers that ask for neither (on loopback). */
    public static final WorkerLink PLAIN = new WorkerLink(null, null);

    /** The connection to talk to the worker over: {@code connected} itself, or TLS over it, handshake done. */
    public Socket secure(Socket connected, String host, int port, int timeoutMs) throws IOException {
        return tls == null ? connected : tls.connect(connected, host, port, timeoutMs);
    }
}
