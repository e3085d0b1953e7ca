package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.habla.security.AuditLog;
import org.junit.jupiter.api.Test;

/** The guard's deadlines, swept on a made-up clock. */
class ConnectionGuardTest {

    private static final long MS = 1_000_000;

    /** A connection as the guard sees it: when it connected, was last active, and since when it is idle (0: not). */
    private static final class Held implements ConnectionGuard.Guarded {
        final List<String> told = new ArrayList<>();
        final long lastActiveMs;
        final long idleSinceMs;

        Held(long lastActiveMs, long idleSinceMs) {
            this.lastActiveMs = lastActiveMs;
            this.idleSinceMs = idleSinceMs;
        }

        @Override
        public long connectedNanos() {
            return MS;
        }

        @Override
        public long lastActiveNanos() {
            return lastActiveMs * MS;
        }

        @Override
        public long idleSinceNanos() {
            return idleSinceMs * MS;
        }

        @Override
        public long frameSinceNanos() {
            return 0;
        }

        @Override
        public ClientId id() {
            return new ClientId("tracker#1", "127.0.0.1:5000");
        }

        @Override
        public void evict(String code, String message) {
            told.add(code + ": " + message);
        }
    }

    private final ConnectionGuard guard = new ConnectionGuard(new ConnectionGuard.Port("control socket 'tracker'",
            "tracker", "limits.maxClientsPerPort", "too_many_clients"), 4,
            Limits.DEFAULTS.withDeadlines(300_000, 10_000, 10_000), AuditLog.withoutFile());

    @Test
    void aReaderWithNothingWaitingForItIsNeverIdleHoweverLongTheSocketIsQuiet() {
        Held quietReader = new Held(1, 0);
        guard.admit(quietReader);
        guard.sweep(3_600_000 * MS);
        assertThat(quietReader.told).isEmpty();
        assertThat(guard.size()).isEqualTo(1);
    }

    @Test
    void aConnectionIdlePastTheDeadlineIsClosedWithTheLimitNamed() {
        Held stalled = new Held(1, 1_000);
        guard.admit(stalled);
        guard.sweep(301_000 * MS);
        assertThat(stalled.told).isEmpty();
        guard.sweep(301_001 * MS);
        assertThat(stalled.told).singleElement().asString().startsWith("idle_timeout: idle for 300001 ms")
                .contains("limits.idleTimeoutMs=300000");
        assertThat(guard.size()).isZero();
    }
}
