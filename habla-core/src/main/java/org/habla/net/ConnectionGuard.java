package org.habla.net;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.config.Limits;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The doorkeeper of one listening port: admits connections and clients under the port's caps, evicting
 * one that only holds its place ({@link AdmissionPolicy}), and closes connections that break a deadline.
 *
 * <pre>
 *   acceptor --admit(newcomer)--&gt; pending full? --yes--&gt; oldest pending.evict("evicted")
 *                                        |
 *                                        v
 *                                     pending  --first whole frame: promote()--&gt; clients full?
 *                                                                                  | no: a client
 *                                                                                  | yes
 *                                                  an idle client.evict("evicted") &lt;-+-&gt; none idle: refused
 *
 *   sweeper, every quarter of the shortest deadline:
 *     any connection: a frame begun more than frameTimeoutMs ago          --&gt; evict("frame_timeout")
 *     a pending one:  connected idleTimeoutMs ago, still no whole frame    --&gt; evict("idle_timeout")
 *     a client:       no frame in and no byte taken for idleTimeoutMs      --&gt; evict("idle_timeout")
 * </pre>
 *
 * What a pending connection reads does not keep it: the bytes a peer's TCP stack takes prove nothing until
 * its buffers are full, which at a sensor's rate takes minutes, so a connection must say something (any
 * request) within {@code idleTimeoutMs}. A client, having spoken, keeps its place by reading too.
 *
 * An evicted connection leaves the counts at once, so the port can take the next one while the evicted one
 * is told why and closed. Thread-safe.
 */
public final class ConnectionGuard implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(ConnectionGuard.class);
    /**
     * Connections the kernel may queue for a guarded port's acceptor, so that a burst of connects does not
     * push a good client into SYN retries (seconds) before the guard can admit it.
     */
    public static final int ACCEPT_BACKLOG = 1_024;
    /** The sweeper never looks more often than this, however short the deadlines. */
    private static final long MIN_SWEEP_MS = 10;
    /** ... nor less often than this, so a deadline is kept to within a second. */
    private static final long MAX_SWEEP_MS = 1_000;

    /** What the guard needs to know of a connection, and how it tells it to go. */
    public interface Guarded {
        /** When it was accepted ({@link System#nanoTime()}). */
        long connectedNanos();

        /** When it last sent a whole frame or its peer took bytes; when it connected before either. */
        long lastActiveNanos();

        /** When the frame it is sending got its first byte, or 0 between frames. */
        long frameSinceNanos();

        /** Tells the peer {@code code} and {@code message} if it can, then closes; must not block. */
        void evict(String code, String message);
    }

    private final String place;
    private final int maxClients;
    private final String clientsCap;
    private final Limits limits;
    private final AdmissionPolicy policy;
    private final List<Guarded> pending = new ArrayList<>();
    private final List<Guarded> clients = new ArrayList<>();
    private final AtomicLong refused = new AtomicLong();
    private final AtomicLong evicted = new AtomicLong();
    private final AtomicLong idleTimeouts = new AtomicLong();
    private final AtomicLong frameTimeouts = new AtomicLong();
    private volatile boolean closed;
    private Thread sweeper;

    /**
     * @param place      the port as messages name it, e.g. {@code control socket 'action'}
     * @param maxClients clients at once
     * @param clientsCap the clients cap's setting as messages name it, e.g. {@code limits.maxClientsPerPort}
     * @param limits     the deadlines, {@code maxPendingPerPort} and {@code evictableIdleMs}
     */
    public ConnectionGuard(String place, int maxClients, String clientsCap, Limits limits) {
        this.place = Objects.requireNonNull(place, "place");
        if (maxClients < 1) {
            throw new IllegalArgumentException("the clients cap must be at least 1, was " + maxClients);
        }
        this.maxClients = maxClients;
        this.clientsCap = Objects.requireNonNull(clientsCap, "clientsCap");
        this.limits = Objects.requireNonNull(limits, "limits");
        this.policy = new AdmissionPolicy(limits.evictableIdleMs());
    }

    /** Starts the sweeper that enforces the deadlines. */
    public synchronized void start() {
        if (sweeper == null) {
            sweeper = Thread.ofVirtual().name("guard-" + place).start(this::sweepLoop);
        }
    }

    /** Lets a new connection in as pending, evicting the pending one idle longest if there are too many. */
    public void admit(Guarded newcomer) {
        Guarded victim = null;
        synchronized (this) {
            if (pending.size() >= limits.maxPendingPerPort()) {
                victim = policy.pendingVictim(pending).orElseThrow();
                pending.remove(victim);
                evicted.incrementAndGet();
            }
            pending.add(newcomer);
        }
        if (victim != null) {
            victim.evict("evicted", policy.pendingReason(place, "limits.maxPendingPerPort=" + limits.maxPendingPerPort()));
        }
    }

    /**
     * Makes a pending connection, which has just sent its first whole frame, a client, evicting an idle
     * client if there are too many.
     *
     * @return empty when it is a client (or was evicted meanwhile); otherwise why not (the caller tells it
     *         and closes it)
     */
    public Optional<String> promote(Guarded connection) {
        Guarded victim;
        String why;
        synchronized (this) {
            if (!pending.remove(connection)) {
                return Optional.empty(); // evicted meanwhile, or already a client
            }
            if (clients.size() < maxClients) {
                clients.add(connection);
                return Optional.empty();
            }
            long now = System.nanoTime();
            victim = policy.clientVictim(clients, now).orElse(null);
            if (victim == null) {
                refused.incrementAndGet();
                return Optional.of(place + " already has " + clientsCap + "=" + maxClients + " clients, every one "
                        + "of them active within limits.evictableIdleMs=" + limits.evictableIdleMs() + " ms");
            }
            why = policy.clientReason(victim, now, place, clientsCap + "=" + maxClients);
            clients.remove(victim);
            clients.add(connection);
            evicted.incrementAndGet();
        }
        LOG.debug("{}: {}", place, why);
        victim.evict("evicted", why);
        return Optional.empty();
    }

    /** Forgets a connection that has closed. */
    public synchronized void left(Guarded connection) {
        if (!pending.remove(connection)) {
            clients.remove(connection);
        }
    }

    /** Connections held now, pending and clients. */
    public synchronized int size() {
        return pending.size() + clients.size();
    }

    /** Clients held now. */
    public synchronized int clients() {
        return clients.size();
    }

    /** Adds the guard's counts to a socket's figures. */
    public void putStats(ObjectNode stats) {
        stats.put("evicted", evicted.get())
                .put("idleTimeouts", idleTimeouts.get())
                .put("frameTimeouts", frameTimeouts.get());
    }

    public long refusedTotal() {
        return refused.get();
    }

    public long evictedTotal() {
        return evicted.get();
    }

    public long idleTimeoutsTotal() {
        return idleTimeouts.get();
    }

    public long frameTimeoutsTotal() {
        return frameTimeouts.get();
    }

    @Override
    public void close() {
        closed = true;
        Thread s;
        synchronized (this) {
            s = sweeper;
        }
        if (s != null) {
            s.interrupt();
        }
    }

    /** One pass over every connection; deadline breakers are evicted. Package-private for tests. */
    void sweep(long now) {
        List<Guarded> late = new ArrayList<>();
        List<String> codes = new ArrayList<>();
        List<String> messages = new ArrayList<>();
        synchronized (this) {
            for (List<Guarded> group : List.of(pending, clients)) {
                for (Guarded g : group) {
                    String[] broken = broken(g, group == pending, now);
                    if (broken != null) {
                        late.add(g);
                        codes.add(broken[0]);
                        messages.add(broken[1]);
                    }
                }
            }
            pending.removeAll(late);
            clients.removeAll(late);
        }
        for (int i = 0; i < late.size(); i++) {
            LOG.debug("{}: closing a connection: {} {}", place, codes.get(i), messages.get(i));
            late.get(i).evict(codes.get(i), messages.get(i));
        }
    }

    /** The code and message of the deadline {@code g} has broken at {@code now}, or null. */
    private String[] broken(Guarded g, boolean isPending, long now) {
        long since = g.frameSinceNanos();
        if (since != 0 && now - since > limits.frameTimeoutMs() * 1_000_000) {
            frameTimeouts.incrementAndGet();
            return new String[] {"frame_timeout", "a frame begun " + (now - since) / 1_000_000
                    + " ms ago is still not whole (limits.frameTimeoutMs=" + limits.frameTimeoutMs() + ")"};
        }
        if (limits.idleTimeoutMs() == 0) {
            return null;
        }
        long idle = now - (isPending ? g.connectedNanos() : g.lastActiveNanos());
        if (idle <= limits.idleTimeoutMs() * 1_000_000) {
            return null;
        }
        idleTimeouts.incrementAndGet();
        return new String[] {"idle_timeout", isPending
                ? "no request within limits.idleTimeoutMs=" + limits.idleTimeoutMs() + " ms of connecting; a "
                        + "client that only reads sends one request (e.g. {\"op\":\"ping\"}) to stay"
                : "nothing sent and nothing taken for " + idle / 1_000_000 + " ms (limits.idleTimeoutMs="
                        + limits.idleTimeoutMs() + ")"};
    }

    private void sweepLoop() {
        long shortest = limits.idleTimeoutMs() > 0
                ? Math.min(limits.idleTimeoutMs(), limits.frameTimeoutMs()) : limits.frameTimeoutMs();
        long tick = Math.clamp(shortest / 4, MIN_SWEEP_MS, MAX_SWEEP_MS);
        while (!closed) {
            try {
                Thread.sleep(tick);
            } catch (InterruptedException e) {
                return;
            }
            try {
                sweep(System.nanoTime());
            } catch (RuntimeException e) {
                LOG.warn("{}: the deadline sweep failed", place, e);
            }
        }
    }
}
