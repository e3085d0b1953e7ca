package org.habla.net;

import java.io.IOException;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.Semaphore;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BooleanSupplier;
import org.habla.security.Tls;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The TLS handshakes of one control socket: each runs on a thread of the connection's own, at most
 * {@code maxPending} at once (a connection beyond that is closed at once and counted as refused); a plain client
 * gets a plain error line ({@code tls_required}) instead of a silence; a secured connection is handed on.
 */
final class TlsHandshakes {

    private static final Logger LOG = LoggerFactory.getLogger(ControlServer.class);

    /** What to do with a connection once it speaks TLS. */
    interface Admit {
        void admit(Socket secured, long n) throws IOException;
    }

    private final String socketName;
    private final Tls tls;
    private final Semaphore pending;
    private final byte[] plainClientError;
    private final AtomicLong refused = new AtomicLong();
    private final AtomicLong plainClients = new AtomicLong();
    private final AtomicLong failures = new AtomicLong();

    TlsHandshakes(String socketName, Tls tls, int maxPending) {
        this.socketName = socketName;
        this.tls = tls;
        this.pending = new Semaphore(maxPending);
        this.plainClientError = (ControlProtocol.error("tls_required", "socket '" + socketName + "' speaks TLS "
                + "only: connect with TLS (openssl s_client -connect HOST:PORT, Python's ssl module); see "
                + "docs/security.md", null).header().toString() + "\n").getBytes(StandardCharsets.UTF_8);
    }

    /**
     * Secures the {@code n}-th connection on a thread of its own and hands it to {@code admit}, unless
     * {@code closed} says the socket closed meanwhile.
     */
    void upgradeThenAdmit(Socket socket, long n, BooleanSupplier closed, Admit admit) {
        if (!pending.tryAcquire()) {
            refused.incrementAndGet();
            closeQuietly(socket);
            return;
        }
        Thread.ofVirtual().name("control-" + socketName + "-" + n + "-tls").start(() -> {
            try {
                Socket secured = tls.upgrade(socket, plainClientError);
                if (closed.getAsBoolean()) {
                    closeQuietly(secured);
                    return;
                }
                admit.admit(secured, n);
            } catch (Tls.PlainClient e) {
                plainClients.incrementAndGet();
                LOG.info("control socket '{}': refused a connection from {}: {}", socketName,
                        socket.getRemoteSocketAddress(), e.getMessage());
            } catch (IOException | RuntimeException e) {
                failures.incrementAndGet();
                LOG.info("control socket '{}': TLS handshake with {} failed: {}", socketName,
                        socket.getRemoteSocketAddress(), e.toString());
                closeQuietly(socket);
            } finally {
                pending.release();
            }
        });
    }

    /** Connections closed because {@code maxPending} handshakes were under way. */
    long refused() {
        return refused.get();
    }

    long plainClients() {
        return plainClients.get();
    }

    long failures() {
        return failures.get();
    }

    static void closeQuietly(Socket socket) {
        try {
            socket.close();
        } catch (IOException e) {
            // nothing left to do with it
        }
    }
}
