package org.habla.sim.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class TicksTest {

    @Test
    void ticksAreRoundAndCoverTheData() {
        Ticks t = Ticks.nice(0, 2.37, 6);
        assertThat(t.step()).isEqualTo(0.5);
        assertThat(t.values()).containsExactly(0.0, 0.5, 1.0, 1.5, 2.0, 2.5);
        assertThat(t.label(1.5)).isEqualTo("1.5");

        Ticks seconds = Ticks.nice(0, 73, 8);
        assertThat(seconds.step()).isEqualTo(10.0);
        assertThat(seconds.max()).isEqualTo(80.0);
        assertThat(seconds.label(30)).isEqualTo("30");
    }

    @Test
    void anEmptyOrBrokenRangeStillGivesAnAxis() {
        assertThat(Ticks.nice(0, 0, 5).max()).isGreaterThan(0);
        assertThat(Ticks.nice(Double.NaN, 1, 5).values()).isNotEmpty();
    }
}
