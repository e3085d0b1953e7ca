package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class AdmissionPolicyTest {

    private static final long MS = 1_000_000;

    /** A connection as the policy sees it; times in ms on a made-up clock. */
    private record Held(String name, long lastActiveMs, String host) implements ConnectionGuard.Guarded {
        Held(String name, long lastActiveMs) {
            this(name, lastActiveMs, "10.0.0.9");
        }

        @Override
        public long connectedNanos() {
            return lastActiveMs * MS;
        }

        @Override
        public long idleSinceNanos() {
            return 0;
        }

        @Override
        public ClientId id() {
            return new ClientId(name, host + ":5000");
        }

        @Override
        public long lastActiveNanos() {
            return lastActiveMs * MS;
        }

        @Override
        public long frameSinceNanos() {
            return 0;
        }

        @Override
        public void evict(String code, String message) {
        }
    }

    private final AdmissionPolicy policy = new AdmissionPolicy(10_000);

    @Test
    void thePendingConnectionWaitingLongestGivesWayToANewcomer() {
        Held old = new Held("old", 9_900);
        Held young = new Held("young", 9_990);
        assertThat(policy.pendingVictim(List.of(young, old), new Held("new", 9_999))).contains(old);
    }

    @Test
    void aFloodFromOneAddressOnlyEvictsItsOwnPendingConnections() {
        Held reader = new Held("reader", 1_000, "10.0.0.30");
        Held flood1 = new Held("flood1", 5_000, "10.0.0.99");
        Held flood2 = new Held("flood2", 6_000, "10.0.0.99");
        assertThat(policy.pendingVictim(List.of(reader, flood1, flood2), new Held("flood3", 7_000, "10.0.0.99")))
                .contains(flood1);
        assertThat(policy.pendingVictim(List.of(reader, flood1), new Held("other", 7_000, "10.0.0.31")))
                .as("a tie between addresses: the oldest of them gives way").contains(reader);
        Held flood3 = new Held("flood3", 7_000, "10.0.0.99");
        assertThat(policy.pendingVictim(List.of(reader, flood1, flood2, flood3), new Held("other", 8_000, "10.0.0.30")))
                .as("the busiest address gives way, not the newcomer's").contains(flood1);
    }

    @Test
    void theClientIdleLongestGivesWayOnceIdlePastTheLimit() {
        Held a = new Held("a", 1_000);
        Held b = new Held("b", 500);
        Held c = new Held("c", 20_000);
        assertThat(policy.clientVictim(List.of(a, b, c), 10_499 * MS)).isEmpty();
        assertThat(policy.clientVictim(List.of(a, b, c), 10_500 * MS)).contains(b);
        assertThat(policy.clientVictim(List.of(a, b, c), 30_000 * MS)).contains(b);
    }

    @Test
    void clientsActiveWithinTheLimitAreNeverEvictedSoTheNewClientIsRefused() {
        List<Held> working = List.of(new Held("a", 99_000), new Held("b", 95_000));
        assertThat(policy.clientVictim(working, 100_000 * MS)).isEmpty();
    }

    @Test
    void theReasonsNameTheLimits() {
        assertThat(policy.pendingReason("control socket 'action'", "limits.maxPendingPerPort=256", "10.0.0.99"))
                .contains("control socket 'action' has limits.maxPendingPerPort=256 connections", "no request",
                        "the most of them from 10.0.0.99");
        assertThat(policy.clientReason(new Held("idle", 0), 20_000 * MS, "control socket 'action'",
                "limits.maxClientsPerPort=16"))
                .contains("control socket 'action' is full (limits.maxClientsPerPort=16)",
                        "idle for 20000 ms (limits.evictableIdleMs=10000)");
    }
}
