package org.habla.net;

import java.util.Collection;
import java.util.Comparator;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * Who gives way on a full port. A port must stay available to a good client while others merely hold
 * connections, and neither a flood of connections nor failing logins may push out the clients that are there.
 * A connection is <em>pending</em> until it is admitted — it sends its first whole, well-formed frame (a request, a
 * place line) or, where the port requires it, authenticates — then it is a <em>client</em>; the two are counted
 * apart:
 *
 * <ol>
 *   <li>A newcomer is always let in. When {@code maxPendingPerPort} connections are already pending, one of the
 *       address that holds the most of them (the newcomer counted) gives way, the one pending longest: a flood of
 *       pending connections only ever evicts its own, and a flood from one address never a connection of
 *       another.</li>
 *   <li>Admission makes a pending connection a client. When {@code maxClientsPerPort} clients are already there,
 *       the client idle longest is evicted for it if it has neither sent a frame nor taken a byte for at least
 *       {@code evictableIdleMs}; when every client is working, the newcomer is refused. Only an admitted connection
 *       ever evicts a client: a connection that has not authenticated never costs a client its place.</li>
 * </ol>
 *
 * Idle means: no whole frame received and no byte taken by the peer's TCP stack, so a client keeps its place
 * for as long as it writes, or reads what the port streams.
 */
final class AdmissionPolicy {

    private static final Comparator<ConnectionGuard.Guarded> IDLE_LONGEST =
            Comparator.comparingLong(ConnectionGuard.Guarded::lastActiveNanos);
    private static final Comparator<ConnectionGuard.Guarded> PENDING_LONGEST =
            Comparator.comparingLong(ConnectionGuard.Guarded::connectedNanos);

    private final long evictableIdleNanos;

    AdmissionPolicy(long evictableIdleMs) {
        if (evictableIdleMs < 0) {
            throw new IllegalArgumentException("evictableIdleMs must not be negative, was " + evictableIdleMs);
        }
        this.evictableIdleNanos = evictableIdleMs * 1_000_000;
    }

    /**
     * The pending connection to evict for {@code newcomer}: of the address with the most pending connections (the
     * newcomer counted; of those addresses, the one whose oldest waited longest), the one pending longest.
     */
    <T extends ConnectionGuard.Guarded> Optional<T> pendingVictim(Collection<T> pending, ConnectionGuard.Guarded newcomer) {
        Map<String, Integer> perHost = new HashMap<>();
        perHost.put(newcomer.id().host(), 1);
        for (T p : pending) {
            perHost.merge(p.id().host(), 1, Integer::sum);
        }
        int most = pending.stream().mapToInt(p -> perHost.get(p.id().host())).max().orElse(0);
        return pending.stream().filter(p -> perHost.get(p.id().host()) == most).min(PENDING_LONGEST);
    }

    /** The client to evict for a new client at {@code nowNanos}, or empty to refuse the new one. */
    <T extends ConnectionGuard.Guarded> Optional<T> clientVictim(Collection<T> clients, long nowNanos) {
        return clients.stream()
                .filter(h -> nowNanos - h.lastActiveNanos() >= evictableIdleNanos)
                .min(IDLE_LONGEST);
    }

    /** Why a pending connection gives way, for its error line. */
    String pendingReason(String place, String cap, String host) {
        return "evicted to admit a newcomer: " + place + " has " + cap + " connections that are not admitted yet "
                + "(no request, or no authentication), the most of them from " + host + ", and this one of them had "
                + "waited longest";
    }

    /** Why a client gives way, for its error line. */
    String clientReason(ConnectionGuard.Guarded victim, long nowNanos, String place, String cap) {
        return "evicted to admit a newcomer: " + place + " is full (" + cap + ") and this client had been idle for "
                + (nowNanos - victim.lastActiveNanos()) / 1_000_000 + " ms (limits.evictableIdleMs="
                + evictableIdleNanos / 1_000_000 + ")";
    }
}
