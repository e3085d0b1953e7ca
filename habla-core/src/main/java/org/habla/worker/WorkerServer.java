package org.habla.worker;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import org.habla.net.Limits;
import org.habla.graph.EngineClock;
import org.habla.net.BlockBudget;
import org.habla.net.ConnectionGuard;
import org.habla.plugin.PluginRegistry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The listening side of {@code habla worker}: accepts daemon connections, each running one placed method
 * in a {@link WorkerSession} of its own. Its {@link ConnectionGuard} keeps the control sockets' rules: at most
 * {@code limits.maxPendingPerPort} connections wait to place a method (the busiest address's that waited longest
 * gives way to a newcomer) and at most {@code limits.maxClientsPerPort} run one ({@code habla worker --max-methods});
 * a place line (after the daemon's proof of the secret, where the worker has one) beyond that evicts a method idle
 * for {@code evictableIdleMs}, or gets a {@code too_many_methods} error line and is closed; a connection that breaks a
 * deadline is closed. A daemon that fails the proof never holds a method's place, and each address may fail it
 * only as often as a {@link org.habla.security.LoginThrottle} allows.
 * The blocks the daemon sends reserve their memory from the worker's {@link BlockBudget} as they arrive.
 */
public final class WorkerServer implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(WorkerServer.class);
    private final PluginRegistry registry;
    private final String bind;
    private final int requestedPort;
    private final EngineClock clock;
    private final Limits limits;
    private final Set<Socket> sessions = ConcurrentHashMap.newKeySet();
    private final ConnectionGuard guard;
    private final BlockBudget budget;
    private final ExecutorService backgroundPool;
    private final org.habla.security.WorkerSecret secret;
    private final org.habla.security.Tls tls;
    private final java.util.concurrent.atomic.AtomicLong authFailures = new java.util.concurrent.atomic.AtomicLong();
    /** The failed proofs each daemon address may make. */
    private final org.habla.security.LoginThrottle throttle = new org.habla.security.LoginThrottle();
    private volatile boolean running;
    private ServerSocket server;
    private Thread acceptor;

    public WorkerServer(PluginRegistry registry, String bind, int port, EngineClock clock, Limits limits) {
        this(registry, bind, port, clock, limits, null, null);
    }

    /**
     * A worker that, with a {@code secret}, places methods only for a daemon that proves it holds the same secret
     * (and proves it back), and with {@code tls} speaks TLS only.
     */
    public WorkerServer(PluginRegistry registry, String bind, int port, EngineClock clock, Limits limits,
            org.habla.security.WorkerSecret secret, org.habla.security.Tls tls) {
        this.secret = secret;
        this.tls = tls;
        this.registry = registry;
        this.bind = bind;
        this.requestedPort = port;
        this.clock = clock;
        this.limits = limits;
        this.guard = new ConnectionGuard(new ConnectionGuard.Port("worker port", "worker", "habla worker --max-methods",
                "too_many_methods"), limits.maxClientsPerPort(), limits, org.habla.security.AuditLog.withoutFile());
        this.budget = BlockBudget.of("limits.processBlockBudgetBytes", limits.processBlockBudgetBytes())
                .child("limits.socketBlockBudgetBytes", limits.socketBlockBudgetBytes());
        this.backgroundPool = org.habla.graph.BackgroundPool.create("habla-worker-background-");
    }

    /** Binds the port and starts accepting. */
    public synchronized void start() throws IOException {
        ServerSocket s;
        try {
            s = org.habla.net.BindAddress.of(bind).listen(requestedPort, ConnectionGuard.ACCEPT_BACKLOG).socket();
        } catch (IOException e) {
            throw new IOException("cannot listen on " + bind + ":" + requestedPort + ": " + e.getMessage(), e);
        }
        server = s;
        running = true;
        guard.start();
        acceptor = Thread.ofPlatform().daemon().name("habla-worker-accept").start(this::acceptLoop);
        LOG.info("HABLA worker listening on {}:{}{}{}; method types: {}", bind, port(),
                secret == null ? "" : ", daemons must prove the shared secret", tls == null ? "" : ", TLS",
                String.join(", ", registry.methods().keySet()));
    }

    /** The bound port (useful when 0 was asked for). */
    public int port() {
        return server.getLocalPort();
    }

    /** Connections open now (placing or running a method). */
    public int sessions() {
        return sessions.size();
    }

    /** Placed methods running now: the connections that count against {@code --max-methods}. */
    public int methodsRunning() {
        return guard.clients();
    }

    /** Bytes held now for blocks still arriving from daemons (the worker's own count). */
    public long blockBytesInFlight() {
        return budget.reserved();
    }

    /** Daemons refused because they did not prove the shared secret, so far. */
    public long authFailures() {
        return authFailures.get();
    }

    /** Connections evicted to admit a newcomer, and closed for a deadline, so far. */
    public long evictions() {
        return guard.evictedTotal() + guard.idleTimeoutsTotal() + guard.frameTimeoutsTotal();
    }

    private void acceptLoop() {
        while (running) {
            Socket s;
            try {
                s = server.accept();
            } catch (IOException e) {
                if (running) {
                    LOG.warn("accept failed: {}", e.toString());
                }
                continue;
            }
            WorkerSession session = new WorkerSession(s, registry, clock, backgroundPool, limits, budget, guard,
                    secret, tls, authFailures, throttle);
            sessions.add(s);
            guard.admit(session);
            Thread.ofVirtual().name("habla-worker-session").start(() -> {
                try {
                    session.run();
                } finally {
                    guard.left(session);
                    sessions.remove(s);
                }
            });
        }
    }

    /** Stops accepting, closes every connection (their methods stop) and the background pool. */
    @Override
    public synchronized void close() {
        running = false;
        guard.close();
        try {
            if (server != null) {
                server.close();
            }
        } catch (IOException e) {
            LOG.debug("close: {}", e.toString());
        }
        for (Socket s : sessions) {
            try {
                s.close();
            } catch (IOException e) {
                LOG.debug("close: {}", e.toString());
            }
        }
        if (acceptor != null) {
            try {
                acceptor.join(2_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        backgroundPool.shutdownNow();
    }
}
