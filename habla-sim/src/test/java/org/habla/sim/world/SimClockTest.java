package org.habla.sim.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

class SimClockTest {

    @Test
    void eachStepRunsEveryParticipantInOrderWithSimTime() {
        SimClock clock = new SimClock(1, 0.01);
        List<String> calls = new ArrayList<>();
        clock.add((now, dt) -> calls.add("a" + Math.round(now * 100)));
        clock.add((now, dt) -> calls.add("b" + Math.round(dt * 100)));
        clock.stepOnce();
        clock.stepOnce();
        assertThat(calls).containsExactly("a1", "b1", "a2", "b1");
        assertThat(clock.nowS()).isCloseTo(0.02, within(1e-12));
    }

    @Test
    void aFailingParticipantDoesNotStopTheOthers() {
        SimClock clock = new SimClock(1, 0.01);
        AtomicInteger ran = new AtomicInteger();
        clock.add((now, dt) -> {
            throw new IllegalStateException("boom");
        });
        clock.add((now, dt) -> ran.incrementAndGet());
        clock.stepOnce();
        clock.stepOnce();
        assertThat(ran).hasValue(2);
    }

    @Test
    void theRunningClockReachesAGivenSimTime() throws InterruptedException {
        try (SimClock clock = new SimClock(20, 0.01)) {
            AtomicInteger steps = new AtomicInteger();
            clock.add((now, dt) -> steps.incrementAndGet());
            clock.start();
            assertThat(clock.awaitSimTime(2.0, 10_000)).isTrue();
            assertThat(steps.get()).isGreaterThanOrEqualTo(200);
        }
    }

    @Test
    void aSpeedBelowRealTimeIsRefused() {
        assertThatThrownBy(() -> new SimClock(0.5, 0.01)).hasMessageContaining("speed");
        assertThat(new SimClock(10, 0.01).realNanos(1.0)).isEqualTo(100_000_000L);
    }
}
