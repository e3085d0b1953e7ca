package org.habla.net;

import java.util.Collection;
import java.util.Comparator;
import java.util.Optional;

/**
 * Who gives way on a full port. A port must stay available to a good client while others merely hold
 * connections, and a flood of connections must not push out the clients that are working. A connection is
 * <em>pending</em> until it sends its first whole, well-formed frame (a request, a place line), then it is a
 * <em>client</em>; the two are counted apart:
 *
 * <ol>
 *   <li>A newcomer is always let in. When {@code maxPendingPerPort} connections are already pending, the
 *       one pending longest is evicted for it: a flood of silent connections only ever evicts itself.</li>
 *   <li>A pending connection's first frame makes it a client. When {@code maxClientsPerPort} clients are
 *       already there, the client idle longest is evicted for it if it has neither sent a frame nor taken a
 *       byte for at least {@code evictableIdleMs}; when every client is working, the newcomer is refused.</li>
 * </ol>
 *
 * Idle means: no whole frame received and no byte taken by the peer's TCP stack, so a client keeps its place
 * for as long as it writes, or reads what the port streams. A good newcomer survives a burst of up to
 * {@code maxPendingPerPort} connections arriving while it says its first line.
 */
final class AdmissionPolicy {

    private static final Comparator<ConnectionGuard.Guarded> IDLE_LONGEST =
            Comparator.comparingLong(ConnectionGuard.Guarded::lastActiveNanos);

    private final long evictableIdleNanos;

    AdmissionPolicy(long evictableIdleMs) {
        if (evictableIdleMs < 0) {
            throw new IllegalArgumentException("evictableIdleMs must not be negative, was " + evictableIdleMs);
        }
        this.evictableIdleNanos = evictableIdleMs * 1_000_000;
    }

    /** The pending connection to evict for a newcomer: the one pending longest. */
    <T extends ConnectionGuard.Guarded> Optional<T> pendingVictim(Collection<T> pending) {
        return pending.stream().min(Comparator.comparingLong(ConnectionGuard.Guarded::connectedNanos));
    }

    /** The client to evict for a new client at {@code nowNanos}, or empty to refuse the new one. */
    <T extends ConnectionGuard.Guarded> Optional<T> clientVictim(Collection<T> clients, long nowNanos) {
        return clients.stream()
                .filter(h -> nowNanos - h.lastActiveNanos() >= evictableIdleNanos)
                .min(IDLE_LONGEST);
    }

    /** Why a pending connection gives way, for its error line. */
    String pendingReason(String place, String cap) {
        return "evicted to admit a newcomer: " + place + " has " + cap + " connections that have sent no "
                + "request, and this one had waited longest";
    }

    /** Why a client gives way, for its error line. */
    String clientReason(ConnectionGuard.Guarded victim, long nowNanos, String place, String cap) {
        return "evicted to admit a newcomer: " + place + " is full (" + cap + ") and this client had been idle for "
                + (nowNanos - victim.lastActiveNanos()) / 1_000_000 + " ms (limits.evictableIdleMs="
                + evictableIdleNanos / 1_000_000 + ")";
    }
}
