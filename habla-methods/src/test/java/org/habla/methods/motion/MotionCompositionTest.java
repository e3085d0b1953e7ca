package org.habla.methods.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class MotionCompositionTest {

    private static double v(Payload p) {
        return ((VectorValue) p).get(0);
    }

    private static double w(Payload p) {
        return ((VectorValue) p).get(1);
    }

    @Test
    void speedRisesNoFasterThanTheAccelerationAndThenFallsSilent() {
        MethodHarness h = MethodHarness.started("compose", new MotionComposition(MotionCompositionParams.defaults()));
        h.push("motion", VectorValue.of(0.2, 0));
        assertThat(v(h.last("motion"))).isCloseTo(0.025, within(1e-12));
        h.advanceMillis(400);
        List<Payload> out = h.values("motion");
        assertThat(out).hasSize(8);
        for (int i = 1; i < out.size(); i++) {
            assertThat(v(out.get(i)) - v(out.get(i - 1))).isLessThanOrEqualTo(0.025 + 1e-12);
        }
        assertThat(v(h.last("motion"))).isEqualTo(0.2);
        h.advanceMillis(500);
        assertThat(h.values("motion")).as("silent once steady").hasSize(8);
    }

    @Test
    void afterAMotionStopTheSameMotionIsRampedUpAgainFromRest() {
        MethodHarness h = MethodHarness.started("compose", new MotionComposition(MotionCompositionParams.defaults()));
        h.push("motion", VectorValue.of(0.2, 0)).advanceMillis(1000).clear();
        h.motionStopped().advanceMillis(500);
        assertThat(h.values("motion")).as("the stop itself is the engine's; nothing is emitted").isEmpty();
        h.push("motion", VectorValue.of(0.2, 0));
        assertThat(v(h.last("motion"))).isCloseTo(0.025, within(1e-12));
        h.advanceMillis(1000);
        assertThat(v(h.last("motion"))).isEqualTo(0.2);
    }

    @Test
    void brakingIsFasterAndAReversalStopsFirst() {
        MethodHarness h = MethodHarness.started("compose", new MotionComposition(MotionCompositionParams.defaults()));
        h.push("motion", VectorValue.of(0.2, 0)).advanceMillis(1000).clear();
        h.push("motion", VectorValue.of(-0.1, 0)).advanceMillis(1000);
        List<Double> speeds = h.values("motion").stream().map(MotionCompositionTest::v).toList();
        double[] braking = {0.15, 0.1, 0.05, 0.0};
        for (int i = 0; i < braking.length; i++) {
            assertThat(speeds.get(i)).isCloseTo(braking[i], within(1e-9));
        }
        assertThat(speeds.get(4)).isCloseTo(-0.025, within(1e-12));
        assertThat(speeds.get(speeds.size() - 1)).isEqualTo(-0.1);
    }

    @Test
    void theTurnRateRampsAndTheLimitsInputCapsTheTarget() {
        MethodHarness h = MethodHarness.started("compose", new MotionComposition(
                ParamsJson.of(MotionCompositionParams.class, "{\"maxRotAccelRadps2\": 4.0}")));
        h.push("limits", RecordValue.builder().put("maxVelMps", 0.1).put("maxRotVelRadps", 0.5).build());
        h.push("motion", VectorValue.of(0.2, 1.0)).advanceMillis(2000);
        assertThat(v(h.last("motion"))).isCloseTo(0.1, within(1e-12));
        assertThat(w(h.last("motion"))).isCloseTo(0.5, within(1e-12));
        assertThat(w(h.values("motion").get(0))).isCloseTo(0.2, within(1e-12));
    }

    @Test
    void garbageIsTakenAsAStop() {
        MotionComposition m = new MotionComposition(MotionCompositionParams.defaults());
        MethodHarness h = MethodHarness.started("compose", m);
        h.push("motion", VectorValue.of(0.1, 0)).advanceMillis(1000);
        h.push("motion", VectorValue.of(Double.POSITIVE_INFINITY, 0)).advanceMillis(1000);
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, 0));
        assertThat(m.malformed()).isEqualTo(1);
    }
}
