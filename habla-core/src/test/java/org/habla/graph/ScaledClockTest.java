package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The sped-up engine clock used against simulated robots whose time runs faster than the wall clock. */
@Timeout(60)
class ScaledClockTest {

    @Test
    void timeAdvancesSpeedTimesFasterThanTheWallClock() throws Exception {
        EngineClock clock = EngineClock.scaled(20);
        try {
            // Each engine reading is bracketed by wall readings, so a thread descheduled between them only widens
            // the bracket: the engine time that passed lies between 20 times the inner and the outer wall time.
            long before0 = System.nanoTime();
            long t0 = clock.nowMicros();
            long after0 = System.nanoTime();
            Thread.sleep(100); // time to pass, not a wait for another thread
            long before1 = System.nanoTime();
            long t1 = clock.nowMicros();
            long after1 = System.nanoTime();
            long advanced = t1 - t0;
            assertThat(advanced).isGreaterThanOrEqualTo((before1 - after0) / 1_000 * 20 - 20);
            assertThat(advanced).isLessThanOrEqualTo((after1 - before0) / 1_000 * 20 + 20);
        } finally {
            clock.close();
        }
    }

    @Test
    void periodicWorkComesSpeedTimesSooner() throws Exception {
        EngineClock clock = EngineClock.scaled(50);
        try {
            CountDownLatch three = new CountDownLatch(3);
            long wall0 = System.nanoTime();
            long t0 = clock.nowMicros();
            // Every 1 s of engine time: at 50x, 60 ms of wall time for three.
            clock.every(1_000_000, three::countDown);
            assertThat(three.await(30, TimeUnit.SECONDS)).as("three runs").isTrue();
            long wallMs = (System.nanoTime() - wall0) / 1_000_000;
            assertThat(clock.nowMicros() - t0).as("not before their engine time").isGreaterThanOrEqualTo(3_000_000);
            // On the wall clock three runs would take 3 s; 3 s here would mean a JVM stalled 50 times longer than
            // the work itself, so this bound holds on a busy machine too.
            assertThat(wallMs).as("sooner than the wall clock's 3 s").isLessThan(3_000);
        } finally {
            clock.close();
        }
    }

    @Test
    void aSpeedBelowOneIsRefused() {
        assertThatThrownBy(() -> EngineClock.scaled(0.5)).isInstanceOf(IllegalArgumentException.class);
    }
}
