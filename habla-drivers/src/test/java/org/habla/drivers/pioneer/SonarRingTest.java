package org.habla.drivers.pioneer;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class SonarRingTest {

    @Test
    void partialUpdatesMergeIntoOneFullRing() {
        SonarRing ring = new SonarRing(4, 5.0);
        ring.put(0, 1.0);
        ring.put(1, 2.0);
        ring.endUpdate();
        assertThat(ring.ready()).isFalse();
        ring.put(2, 3.0);
        ring.put(3, 4.0);
        ring.endUpdate();
        assertThat(ring.ready()).isTrue();
        ring.put(1, 0.5);
        ring.endUpdate();
        assertThat(ring.snapshot()).containsExactly(1.0, 0.5, 3.0, 4.0);
    }

    @Test
    void aRingWithASilentTransducerIsPublishedAfterItsPatienceWithTheMaximumRange() {
        SonarRing ring = new SonarRing(3, 5.0);
        for (int i = 0; i < SonarRing.PATIENCE_UPDATES - 1; i++) {
            ring.put(0, 1.0);
            ring.put(1, 1.5);
            ring.endUpdate();
            assertThat(ring.ready()).isFalse();
        }
        ring.put(0, 1.0);
        ring.endUpdate();
        assertThat(ring.ready()).isTrue();
        assertThat(ring.snapshot()).containsExactly(1.0, 1.5, 5.0);
    }

    @Test
    void anIndexBeyondTheRobotsTransducersIsRefused() {
        SonarRing ring = new SonarRing(16, 5.0);
        assertThat(ring.put(16, 1.0)).isFalse();
        assertThat(ring.put(-1, 1.0)).isFalse();
        assertThat(ring.put(15, 1.0)).isTrue();
    }
}
