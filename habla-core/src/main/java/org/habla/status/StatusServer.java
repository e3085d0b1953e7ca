package org.habla.status;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Objects;
import java.util.function.Supplier;
import org.habla.net.Limits;
import org.habla.config.StatusConfig;
import org.habla.net.BindAddress;
import org.habla.net.ConnectionGuard;
import org.habla.security.AuditLog;
import org.habla.security.PortAccess;
import org.habla.security.PortSecurity;
import org.habla.security.Principal;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The daemon's status endpoint: a TCP server that writes the current snapshot (rates, latencies, queue drops,
 * link states, as the engine assembles them) as one JSON line to each client that connects, then closes.
 * {@code nc 127.0.0.1 7099} is a complete client. Port 0 in the config turns it off.
 *
 * <p>At most {@code limits.maxPendingPerPort} answers are in flight at once; a newcomer to a full endpoint
 * is answered and the oldest answer in flight is abandoned. A client that has not taken its whole line
 * within {@code limits.frameTimeoutMs} is disconnected. See {@link ConnectionGuard}.
 *
 * <p>Where authentication is on ({@link PortAccess}), the endpoint first sends
 * {@code {"type":"hello","protocol":"habla-status/1","auth":"required"}} and waits (within
 * {@code limits.frameTimeoutMs}) for the client's auth line; a client with the {@code read} role on
 * {@code "@status"} (or {@code "*"}) gets the snapshot, any other an error line after a short delay; every refused
 * login is counted and goes to the audit log, as on a control socket.
 */
public final class StatusServer implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(StatusServer.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    /** The protocol named in the hello an endpoint that requires authentication sends. */
    public static final String PROTOCOL = "habla-status/1";

    private final StatusConfig config;
    private final Supplier<ObjectNode> snapshot;
    private final ConnectionGuard guard;
    private final Limits limits;
    private final PortSecurity security;
    /** The longest {@link #close} waits for the acceptor to leave {@code accept}, which is when the port is released. */
    private static final long ACCEPTOR_STOP_MILLIS = 2_000;

    private volatile ServerSocket listener;
    private volatile Thread acceptor;
    private volatile boolean closed;

    public StatusServer(StatusConfig config, Supplier<ObjectNode> snapshot) {
        this(config, Limits.DEFAULTS, snapshot);
    }

    public StatusServer(StatusConfig config, Limits limits, Supplier<ObjectNode> snapshot) {
        this(config, limits, snapshot, PortAccess.open(Principal.STATUS));
    }

    /** An endpoint that answers only the clients {@code access} admits. */
    public StatusServer(StatusConfig config, Limits limits, Supplier<ObjectNode> snapshot, PortAccess access) {
        this(config, limits, snapshot, access, null);
    }

    /** An endpoint that answers only the clients {@code access} admits, over TLS unless {@code tls} is null. */
    public StatusServer(StatusConfig config, Limits limits, Supplier<ObjectNode> snapshot, PortAccess access,
            org.habla.security.Tls tls) {
        this(config, limits, snapshot, new PortSecurity(access, AuditLog.withoutFile(), tls));
    }

    /**
     * An endpoint guarded by {@code security}: who may read it, where its refused logins and the connections it
     * evicts are audited, whether it speaks TLS.
     */
    public StatusServer(StatusConfig config, Limits limits, Supplier<ObjectNode> snapshot, PortSecurity security) {
        this.security = Objects.requireNonNull(security, "security");
        this.limits = Objects.requireNonNull(limits, "limits");
        this.config = Objects.requireNonNull(config, "config");
        this.snapshot = Objects.requireNonNull(snapshot, "snapshot");
        this.guard = new ConnectionGuard(new ConnectionGuard.Port("the status endpoint", Principal.STATUS,
                "limits.maxClientsPerPort", "too_many_clients"), limits.maxClientsPerPort(), limits, security.audit());
    }

    /**
     * Binds the config's port without answering anyone yet (so a daemon holds all its ports before it serves on
     * any); does nothing when the port is 0 (the endpoint is off).
     */
    public void bind() throws IOException {
        bind(config.port());
    }

    /** Binds (unless {@link #bind} did) and starts answering; does nothing when the config's port is 0. */
    public void start() throws IOException {
        if (listener == null) {
            bind(config.port());
        }
        accept();
    }

    /** Binds to an ephemeral port whatever the config says (tests, several daemons on one machine). */
    public void startOnAnyPort() throws IOException {
        bind(-1);
        accept();
    }

    private void bind(int port) throws IOException {
        if (listener != null) {
            throw new IllegalStateException("the status endpoint is already bound");
        }
        if (port == 0) {
            return;
        }
        String bind = bindAddress();
        ServerSocket server;
        try {
            server = BindAddress.of(bind).listen(Math.max(port, 0), ConnectionGuard.ACCEPT_BACKLOG).socket();
        } catch (IOException e) {
            throw new IOException("status endpoint cannot listen on " + bind + ":" + port + ": " + e.getMessage(), e);
        }
        listener = server;
    }

    private void accept() {
        ServerSocket server = listener;
        if (server == null) {
            LOG.info("status endpoint is off (port 0)");
            return;
        }
        String bind = bindAddress();
        guard.start();
        Thread a = new Thread(this::acceptLoop, "status-accept");
        a.setDaemon(true);
        acceptor = a;
        a.start();
        LOG.info("status endpoint listening on {}:{}", bind, server.getLocalPort());
    }

    private String bindAddress() {
        return config.bind() == null || config.bind().isBlank() ? BindAddress.DEFAULT : config.bind();
    }

    /** Whether the endpoint is listening. */
    public boolean running() {
        return listener != null && !closed;
    }

    /** The bound port. */
    public int port() {
        ServerSocket s = listener;
        if (s == null) {
            throw new IllegalStateException("the status endpoint is not listening");
        }
        return s.getLocalPort();
    }

    /** Who may read the endpoint, and its counts of authentications. */
    public PortAccess access() {
        return security.access();
    }

    /** Answers being written now. */
    public int answering() {
        return guard.size();
    }

    @Override
    public void close() {
        closed = true;
        guard.close();
        ServerSocket s = listener;
        if (s != null) {
            try {
                s.close();
            } catch (IOException e) {
                LOG.debug("closing the status endpoint: {}", e.toString());
            }
        }
        Thread a = acceptor;
        if (a != null && a != Thread.currentThread()) {
            try {
                a.join(ACCEPTOR_STOP_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private void acceptLoop() {
        while (!closed) {
            Socket client;
            try {
                client = listener.accept();
            } catch (IOException e) {
                if (!closed) {
                    LOG.warn("status endpoint stopped accepting: {}", e.toString());
                }
                return;
            }
            StatusAnswer answer = new StatusAnswer(client, snapshot, guard, limits, security);
            guard.admit(answer);
            Thread.ofVirtual().name("status-client").start(answer::run);
        }
    }
}
