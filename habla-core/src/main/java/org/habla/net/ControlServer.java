package org.habla.net;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.security.PortSecurity;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The TCP server of one exposed method: every client gets the method's hello, its samples as they come,
 * and may write values to its control inputs (protocol {@code habla-control/1}, see {@link ControlProtocol}
 * and {@code docs/protocol.md}).
 *
 * <pre>
 *   engine --samples, staleness--&gt; listener (encodes once, only enqueues) --&gt; client 1 outbox --&gt; writer
 *                                    (same bytes, rotating order)      \--&gt; client 2 outbox --&gt; writer
 *   acceptor thread --&gt; ConnectionGuard (cap, eviction, deadlines) --&gt; ControlClient per connection
 *                                                                       (virtual threads)
 * </pre>
 *
 * The engine's listener never blocks and never does I/O; a client that stops reading loses its oldest
 * samples (counted, and told) and delays nobody else. A newcomer is always let in; at most
 * {@code maxPendingPerPort} connections wait to be admitted (a first request; where the port requires it, an
 * authentication) and at most {@code maxClientsPerPort} clients hold the port, and a full port evicts one that only
 * holds its place ({@link AdmissionPolicy}). The blocks clients write reserve their memory from the port's
 * {@link BlockBudget} as they arrive.
 */
public final class ControlServer implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(ControlServer.class);

    private final ControlPoint point;
    private final Expose expose;
    private final Limits limits;
    private final ControlProtocol protocol;
    private final ControlLease lease;
    private final ConnectionGuard guard;
    private final BlockBudget budget;
    private final PortSecurity security;
    private final List<ControlClient> clients = new CopyOnWriteArrayList<>();
    private final Counters counters = new Counters();
    private final AtomicLong droppedByGone = new AtomicLong();
    /** TLS handshakes in progress, at most {@code limits.maxPendingPerPort}; null on a plain socket. */
    private final TlsHandshakes handshakes;
    /**
     * The longest {@link #close} waits for the acceptor to leave its {@code accept}: the operating system releases
     * the port only then, so a daemon started right after this one closed can have it.
     */
    static final long ACCEPTOR_STOP_MILLIS = 2_000;

    private volatile ServerSocket listener;
    private volatile Thread acceptor;
    private volatile ControlPoint.Subscription subscription;
    private volatile boolean closed;

    /** The server's running counts. */
    static final class Counters {
        final AtomicLong connections = new AtomicLong();
        final AtomicLong linesIn = new AtomicLong();
        final AtomicLong linesOut = new AtomicLong();
        final AtomicLong errors = new AtomicLong();
    }

    /** A server with a block budget of its own for the process's share (one server alone, tests). */
    public ControlServer(ControlPoint point, Expose expose, Limits limits) {
        this(point, expose, limits, BlockBudget.of("limits.processBlockBudgetBytes", limits.processBlockBudgetBytes()));
    }

    /** A server whose port's block budget is part of {@code processBudget}, shared by every port of the daemon. */
    public ControlServer(ControlPoint point, Expose expose, Limits limits, BlockBudget processBudget) {
        this(point, expose, limits, processBudget, PortSecurity.open(point.name()));
    }

    /**
     * A server whose port's block budget is part of {@code processBudget}, guarded by {@code security}: who may
     * use it, where its commands are audited, whether it speaks TLS.
     */
    public ControlServer(ControlPoint point, Expose expose, Limits limits, BlockBudget processBudget,
            PortSecurity security) {
        this.security = Objects.requireNonNull(security, "security");
        this.point = Objects.requireNonNull(point, "point");
        this.expose = Objects.requireNonNull(expose, "expose");
        this.limits = Objects.requireNonNull(limits, "limits");
        this.lease = point.lease().orElse(null);
        this.protocol = new ControlProtocol(point, limits, lease, security);
        this.guard = new ConnectionGuard(new ConnectionGuard.Port("control socket '" + point.name() + "'", point.name(),
                "limits.maxClientsPerPort", "too_many_clients"), limits.maxClientsPerPort(), limits, security.audit());
        this.budget = processBudget.child("limits.socketBlockBudgetBytes", limits.socketBlockBudgetBytes());
        this.handshakes = security.tls() == null ? null
                : new TlsHandshakes(point.name(), security.tls(), limits.maxPendingPerPort());
    }

    /**
     * Binds the port without accepting anyone yet, so a daemon can hold all its ports before it serves on any.
     * A connection that arrives before {@link #start} waits in the backlog (and is reset if the server closes).
     */
    public void bind() throws IOException {
        if (listener != null) {
            throw new IllegalStateException("control socket '" + point.name() + "' is already bound");
        }
        String bind = bindAddress();
        // A channel's socket: what it accepts are channels, so a plain connection can be written without waiting.
        // It listens on exactly the address asked for (0.0.0.0 is IPv4 only; see BindAddress).
        ServerSocket server;
        try {
            server = BindAddress.of(bind).listen(expose.port(), ConnectionGuard.ACCEPT_BACKLOG).socket();
        } catch (IOException e) {
            throw new IOException("control socket '" + point.name() + "' of method " + point.methodId()
                    + " cannot listen on " + bind + ":" + expose.port() + ": " + e.getMessage(), e);
        }
        listener = server;
    }

    /** Binds the port if {@link #bind} was not called, and starts accepting clients. */
    public void start() throws IOException {
        if (subscription != null) {
            throw new IllegalStateException("control socket '" + point.name() + "' is already started");
        }
        if (listener == null) {
            bind();
        }
        String bind = bindAddress();
        subscription = point.subscribe(new ControlFanout(point.name(), clients));
        guard.start();
        Thread a = new Thread(this::acceptLoop, "control-" + point.name() + "-accept");
        a.setDaemon(true);
        acceptor = a;
        a.start();
        LOG.info("control socket '{}' of method {} listening on {}:{}", point.name(), point.methodId(), bind, port());
    }

    private String bindAddress() {
        return expose.bind() == null || expose.bind().isBlank() ? "127.0.0.1" : expose.bind();
    }

    /** The bound port (useful when the config asked for port 0). */
    public int port() {
        ServerSocket s = listener;
        if (s == null) {
            throw new IllegalStateException("control socket '" + point.name() + "' is not started");
        }
        return s.getLocalPort();
    }

    public int clientCount() {
        return clients.size();
    }

    /**
     * Clients now and in total, refused connections, lines each way, dropped samples and protocol errors; on an
     * actuating socket, who commands it ({@code control}).
     */
    public ObjectNode stats() {
        long dropped = droppedByGone.get();
        for (ControlClient c : clients) {
            dropped += c.dropped();
        }
        ObjectNode stats = JsonNodeFactory.instance.objectNode()
                .put("socket", point.name())
                .put("port", listener == null ? expose.port() : port())
                .put("clients", clients.size())
                .put("connections", counters.connections.get())
                .put("refused", guard.refusedTotal() + (handshakes == null ? 0 : handshakes.refused()))
                .put("linesIn", counters.linesIn.get())
                .put("linesOut", counters.linesOut.get())
                .put("dropped", dropped)
                .put("errors", counters.errors.get());
        guard.putStats(stats);
        security.access().putStats(stats);
        stats.put("tls", security.tls() != null);
        if (handshakes != null) {
            stats.put("plainClientsRefused", handshakes.plainClients()).put("tlsFailures", handshakes.failures());
        }
        stats.put("blockBytes", budget.reserved());
        if (lease != null) {
            stats.set("control", lease.status());
        }
        return stats;
    }

    /** Bytes this port holds now for blocks still arriving. */
    public long blockBytesInFlight() {
        return budget.reserved();
    }

    @Override
    public void close() {
        closed = true;
        ControlPoint.Subscription s = subscription;
        if (s != null) {
            s.close();
        }
        guard.close();
        ServerSocket l = listener;
        if (l != null) {
            try {
                l.close();
            } catch (IOException e) {
                LOG.debug("closing control socket '{}': {}", point.name(), e.toString());
            }
        }
        awaitAcceptorGone();
        for (ControlClient c : clients) {
            c.close();
        }
    }

    private void awaitAcceptorGone() {
        Thread a = acceptor;
        if (a == null || a == Thread.currentThread()) {
            return;
        }
        try {
            a.join(ACCEPTOR_STOP_MILLIS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void acceptLoop() {
        long n = 0;
        while (!closed) {
            Socket socket;
            try {
                socket = listener.accept();
            } catch (IOException e) {
                if (!closed) {
                    LOG.warn("control socket '{}' stopped accepting: {}", point.name(), e.toString());
                }
                return;
            }
            long number = ++n;
            if (handshakes != null) {
                handshakes.upgradeThenAdmit(socket, number, () -> closed, this::admit);
                continue;
            }
            try {
                admit(socket, number);
            } catch (IOException | RuntimeException e) {
                LOG.warn("control socket '{}': could not admit {}: {}", point.name(),
                        socket.getRemoteSocketAddress(), e.toString());
                TlsHandshakes.closeQuietly(socket);
            }
        }
    }

    private void admit(Socket socket, long n) throws IOException {
        socket.setTcpNoDelay(true);
        String label = "control-" + point.name() + "-" + n;
        ControlClient[] self = new ControlClient[1];
        ClientId id = new ClientId(point.name() + "#" + n,
                socket.getInetAddress().getHostAddress() + ":" + socket.getPort());
        ControlConnection connection = socket.getChannel() != null && !(socket instanceof javax.net.ssl.SSLSocket)
                ? new ChannelConnection(socket.getChannel(), ChannelReadiness.shared())
                : ControlConnection.of(socket);
        self[0] = new ControlClient(connection, label, id, protocol, limits, budget, guard, counters, () -> {
            guard.left(self[0]);
            if (clients.remove(self[0])) {
                droppedByGone.addAndGet(self[0].dropped());
            }
        });
        clients.add(self[0]); // before admission: if it is evicted at once, its close removes it again
        guard.admit(self[0]);
        counters.connections.incrementAndGet();
        LOG.debug("{}: connected from {}", label, socket.getRemoteSocketAddress());
        self[0].start();
    }
}
