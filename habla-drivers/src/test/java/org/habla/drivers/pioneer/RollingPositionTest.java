package org.habla.drivers.pioneer;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class RollingPositionTest {

    @Test
    void theFirstValueSetsTheStart() {
        assertThat(new RollingPosition().update(1000)).isEqualTo(1000);
    }

    @Test
    void aFirstValueInTheUpperHalfIsReadAsJustBelowZero() {
        assertThat(new RollingPosition().update(32750)).isEqualTo(-18);
    }

    @Test
    void drivingForwardAcrossTheFifteenBitBoundaryKeepsCounting() {
        RollingPosition p = new RollingPosition();
        p.update(16000);
        assertThat(p.update(30000)).isEqualTo(30000);
        assertThat(p.update(32767)).isEqualTo(32767);
        assertThat(p.update(10)).isEqualTo(32768 + 10);
        assertThat(p.update(300)).isEqualTo(32768 + 300);
    }

    @Test
    void drivingBackwardAcrossZeroGoesNegative() {
        RollingPosition p = new RollingPosition();
        p.update(0);
        assertThat(p.update(32750)).isEqualTo(-18);
        assertThat(p.update(32500)).isEqualTo(-268);
        assertThat(p.update(5)).isEqualTo(5);
    }

    @Test
    void manyLapsOfTheCounterAddUp() {
        RollingPosition p = new RollingPosition();
        long expected = 0;
        int raw = 0;
        p.update(raw);
        for (int i = 0; i < 1000; i++) {
            raw = (raw + 250) & 0x7FFF;
            expected += 250;
            assertThat(p.update(raw)).isEqualTo(expected);
        }
        assertThat(expected).isGreaterThan(7 * 32768L);
    }
}
