package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class AdmissionPolicyTest {

    private static final long MS = 1_000_000;

    /** A connection as the policy sees it; times in ms on a made-up clock. */
    private record Held(String name, long lastActiveMs) implements ConnectionGuard.Guarded {
        @Override
        public long connectedNanos() {
            return lastActiveMs * MS;
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
        assertThat(policy.pendingVictim(List.of(young, old))).contains(old);
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
        assertThat(policy.pendingReason("control socket 'action'", "limits.maxPendingPerPort=256"))
                .contains("control socket 'action' has limits.maxPendingPerPort=256 connections", "no request");
        assertThat(policy.clientReason(new Held("idle", 0), 20_000 * MS, "control socket 'action'",
                "limits.maxClientsPerPort=16"))
                .contains("control socket 'action' is full (limits.maxClientsPerPort=16)",
                        "idle for 20000 ms (limits.evictableIdleMs=10000)");
    }
}
