// Over 300 lines, on purpose: admitting, evicting and closing on a deadline share one lock over the pending and
// client lists, and each leaves the same log line and audit entry; who gives way is AdmissionPolicy's.
package org.habla.net;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.security.AuditEntry;
import org.habla.security.AuditLog;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The doorkeeper of one listening port: admits connections and clients under the port's caps, evicting
 * one that only holds its place ({@link AdmissionPolicy}), and closes connections that break a deadline. Every
 * connection it evicts, closes or refuses is logged at INFO with the reason and goes to the port's audit log.
 *
 * <pre>
 *   acceptor --admit(newcomer)--&gt; pending full? --yes--&gt; the busiest address's oldest pending.evict("evicted")
 *                                        |
 *                                        v
 *                                     pending  --admitted (first frame, or authenticated): promote()--&gt; clients full?
 *                                                                                  | no: a client
 *                                                                                  | yes
 *                                                  an idle client.evict("evicted") &lt;-+-&gt; none idle: refused
 *
 *   sweeper, every quarter of the shortest deadline:
 *     any connection: a frame begun more than frameTimeoutMs ago                      --&gt; evict("frame_timeout")
 *     any connection: idle (see Guarded#idleSinceNanos) for more than idleTimeoutMs    --&gt; evict("idle_timeout")
 * </pre>
 *
 * A connection that only reads is not idle: however quiet the port, it stays while it takes what it is sent. It
 * is idle when lines wait for it that its peer does not take, or when it can read nothing until it speaks (it has
 * not authenticated). Connection holders that read are kept off by the caps: a full port evicts the client idle
 * longest, a flood of pending connections evicts its own address's.
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
    /** What an entry of the audit log says a connection tried: to hold a place on the port. */
    public static final String AUDIT_ACTION = "connect";
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

        /**
         * Since when it has been idle ({@link System#nanoTime()}), or 0 while it is not: it is idle while lines wait
         * for it that its peer has not taken, since the later of their arrival and {@link #lastActiveNanos}, and
         * while it can read nothing until it speaks, since it connected. A reader that takes all it is sent is never
         * idle.
         */
        long idleSinceNanos();

        /** What its idleness is, for the {@code idle_timeout} message. */
        default String idleness() {
            return "it took nothing of the lines waiting for it and sent nothing";
        }

        /** When the frame it is sending got its first byte, or 0 between frames. */
        long frameSinceNanos();

        /** Who it is, for the log and the audit log. */
        ClientId id();

        /** Tells the peer {@code code} and {@code message} if it can, then closes; must not block. */
        void evict(String code, String message);
    }

    /**
     * How a guarded port is named.
     *
     * @param place      in messages, e.g. {@code control socket 'action'}
     * @param key        in the audit log: a socket's name, {@code @status}, {@code worker}
     * @param clientsCap the clients cap's setting as messages name it, e.g. {@code limits.maxClientsPerPort}
     * @param fullCode   the error code of a newcomer refused because every client works, e.g. {@code too_many_clients}
     */
    public record Port(String place, String key, String clientsCap, String fullCode) {
        public Port {
            Objects.requireNonNull(place, "place");
            Objects.requireNonNull(key, "key");
            Objects.requireNonNull(clientsCap, "clientsCap");
            Objects.requireNonNull(fullCode, "fullCode");
        }
    }

    private final Port port;
    private final String place;
    private final int maxClients;
    private final Limits limits;
    private final AuditLog audit;
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
     * @param maxClients clients at once
     * @param limits     the deadlines, {@code maxPendingPerPort} and {@code evictableIdleMs}
     * @param audit      where evictions and refusals are audited
     */
    public ConnectionGuard(Port port, int maxClients, Limits limits, AuditLog audit) {
        this.port = Objects.requireNonNull(port, "port");
        this.place = port.place();
        if (maxClients < 1) {
            throw new IllegalArgumentException("the clients cap must be at least 1, was " + maxClients);
        }
        this.maxClients = maxClients;
        this.limits = Objects.requireNonNull(limits, "limits");
        this.audit = Objects.requireNonNull(audit, "audit");
        this.policy = new AdmissionPolicy(limits.evictableIdleMs());
    }

    /** Starts the sweeper that enforces the deadlines. */
    public synchronized void start() {
        if (sweeper == null) {
            sweeper = Thread.ofVirtual().name("guard-" + place).start(this::sweepLoop);
        }
    }

    /**
     * Lets a new connection in as pending; if there are too many, the busiest address's pending connection that
     * waited longest gives way ({@link AdmissionPolicy#pendingVictim}).
     */
    public void admit(Guarded newcomer) {
        Guarded victim = null;
        synchronized (this) {
            if (pending.size() >= limits.maxPendingPerPort()) {
                victim = policy.pendingVictim(pending, newcomer).orElseThrow();
                pending.remove(victim);
                evicted.incrementAndGet();
            }
            pending.add(newcomer);
        }
        if (victim != null) {
            close(victim, "evicted", policy.pendingReason(place, "limits.maxPendingPerPort="
                    + limits.maxPendingPerPort(), victim.id().host()));
        }
    }

    /**
     * Makes a pending connection, which has just been admitted (its first whole frame on an open port, its
     * authentication where the port requires it), a client, evicting an idle client if there are too many.
     * A refusal is logged and audited here.
     *
     * @return empty when it is a client (or was evicted meanwhile); otherwise why not (the caller tells it, with
     *         {@link Port#fullCode}, and closes it)
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
                why = place + " already has " + port.clientsCap() + "=" + maxClients + " clients, every one "
                        + "of them active within limits.evictableIdleMs=" + limits.evictableIdleMs() + " ms";
            } else {
                why = policy.clientReason(victim, now, place, port.clientsCap() + "=" + maxClients);
                clients.remove(victim);
                clients.add(connection);
                evicted.incrementAndGet();
            }
        }
        if (victim == null) {
            record(connection, port.fullCode(), why);
            return Optional.of(why);
        }
        close(victim, "evicted", why);
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
        List<String[]> why = new ArrayList<>();
        synchronized (this) {
            for (List<Guarded> group : List.of(pending, clients)) {
                for (Guarded g : group) {
                    String[] broken = broken(g, now);
                    if (broken != null) {
                        late.add(g);
                        why.add(broken);
                    }
                }
            }
            pending.removeAll(late);
            clients.removeAll(late);
        }
        for (int i = 0; i < late.size(); i++) {
            close(late.get(i), why.get(i)[0], why.get(i)[1]);
        }
    }

    /** Tells {@code g} why it goes, after logging and auditing it. */
    private void close(Guarded g, String code, String message) {
        record(g, code, message);
        g.evict(code, message);
    }

    /** One INFO line and one audit entry for a connection the port evicts, closes or refuses. */
    private void record(Guarded g, String code, String message) {
        ClientId id = g.id();
        LOG.info("{}: {} {}: {}", place, code, id, message);
        audit.add(new AuditEntry(Instant.now(), id.client(), id.address(), port.key(), AUDIT_ACTION, null, null,
                false, code + ": " + message));
    }

    /** The code and message of the deadline {@code g} has broken at {@code now}, or null. */
    private String[] broken(Guarded g, long now) {
        long since = g.frameSinceNanos();
        if (since != 0 && now - since > limits.frameTimeoutMs() * 1_000_000) {
            frameTimeouts.incrementAndGet();
            return new String[] {"frame_timeout", "a frame begun " + (now - since) / 1_000_000
                    + " ms ago is still not whole (limits.frameTimeoutMs=" + limits.frameTimeoutMs() + ")"};
        }
        long idleSince = g.idleSinceNanos();
        if (limits.idleTimeoutMs() == 0 || idleSince == 0 || now - idleSince <= limits.idleTimeoutMs() * 1_000_000) {
            return null;
        }
        idleTimeouts.incrementAndGet();
        return new String[] {"idle_timeout", "idle for " + (now - idleSince) / 1_000_000 + " ms (limits.idleTimeoutMs="
                + limits.idleTimeoutMs() + "): " + g.idleness()};
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
