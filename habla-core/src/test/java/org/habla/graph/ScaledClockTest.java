package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The sped-up engine clock used against simulated robots whose time runs faster than the wall clock. */
@Timeout(10)
class ScaledClockTest {

    @Test
    void timeAdvancesSpeedTimesFasterThanTheWallClock() throws Exception {
        EngineClock clock = EngineClock.scaled(20);
        try {
            long wall0 = System.nanoTime();
            long t0 = clock.nowMicros();
            Thread.sleep(100);
            long wallMicros = (System.nanoTime() - wall0) / 1_000;
            long advanced = clock.nowMicros() - t0;
            assertThat(advanced).isGreaterThanOrEqualTo((long) (wallMicros * 20 * 0.9));
            assertThat(advanced).isLessThanOrEqualTo((long) (wallMicros * 20 * 1.1) + 20_000);
        } finally {
            clock.close();
        }
    }

    @Test
    void periodicWorkComesSpeedTimesSooner() throws Exception {
        EngineClock clock = EngineClock.scaled(50);
        try {
            CountDownLatch three = new CountDownLatch(3);
            // Every 1 s of engine time: three of them well inside 1 s of wall time at 50x.
            clock.every(1_000_000, three::countDown);
            assertThat(three.await(1, TimeUnit.SECONDS)).isTrue();
        } finally {
            clock.close();
        }
    }

    @Test
    void aSpeedBelowOneIsRefused() {
        assertThatThrownBy(() -> EngineClock.scaled(0.5)).isInstanceOf(IllegalArgumentException.class);
    }
}
