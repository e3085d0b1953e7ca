package org.habla.methods.locomotion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class GaitCompositionTest {

    private static double[] walk(MethodHarness h) {
        return ((VectorValue) h.last("walk")).toArray();
    }

    @Test
    void aMotionWithinTheLimitsBecomesForwardAndRotateWithoutStrafe() {
        MethodHarness h = MethodHarness.started("gait", new GaitComposition(GaitCompositionParams.defaults()));
        h.push("motion", VectorValue.of(0.1, -0.6));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(0.1, 0, -0.6));
    }

    @Test
    void aMotionTooFastIsShrunkAsAWholeSoTheCurveStays() {
        MethodHarness h = MethodHarness.started("gait", new GaitComposition(GaitCompositionParams.defaults()));
        h.push("motion", VectorValue.of(0.36, 0.6));
        double[] w = walk(h);
        assertThat(w[0]).isCloseTo(0.18, within(1e-12));
        assertThat(w[2]).isCloseTo(0.3, within(1e-12));
        assertThat(w[0] / w[2]).as("radius of the curve").isCloseTo(0.36 / 0.6, within(1e-12));
        h.push("motion", VectorValue.of(-0.15, 0));
        assertThat(walk(h)[0]).isCloseTo(-0.15, within(1e-12));
    }

    @Test
    void aStrafeShareWalksPartOfATurnSidewaysAndAThirdElementIsStrafe() {
        GaitCompositionParams p = ParamsJson.of(GaitCompositionParams.class, "{\"strafeShare\": 0.5, \"strafeMpsPerRadps\": 0.1}");
        MethodHarness h = MethodHarness.started("gait", new GaitComposition(p));
        h.push("motion", VectorValue.of(0, 0.6));
        double[] w = walk(h);
        assertThat(w[1]).as("strafe to the left for a left turn").isCloseTo(0.03, within(1e-12));
        assertThat(w[2]).isCloseTo(0.3, within(1e-12));
        MethodHarness plain = MethodHarness.started("gait", new GaitComposition(GaitCompositionParams.defaults()));
        plain.push("motion", VectorValue.of(0.05, 0, -0.08));
        assertThat(plain.last("walk")).isEqualTo(VectorValue.of(0.05, -0.08, 0));
    }

    @Test
    void scaleParamsAdaptAWheeledRobotsSpeedsAndGarbageStops() {
        GaitCompositionParams p = ParamsJson.of(GaitCompositionParams.class, "{\"forwardScale\": 0.5, \"rotateScale\": 2.0}");
        GaitComposition g = new GaitComposition(p);
        MethodHarness h = MethodHarness.started("gait", g);
        h.push("motion", VectorValue.of(0.2, 0.3));
        double[] w = walk(h);
        assertThat(w[0]).isCloseTo(0.1, within(1e-12));
        assertThat(w[2]).isCloseTo(0.6, within(1e-12));
        h.push("motion", VectorValue.of(Double.POSITIVE_INFINITY, 0));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(0, 0, 0));
        h.push("motion", VectorValue.of(1));
        assertThat(g.rejected()).isEqualTo(2);
    }
}
