package org.habla.methods.sensors;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.habla.method.MethodHarness;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class OdometryTest {

    private static RecordValue odometry(double x, double y, double theta) {
        return RecordValue.builder().put("xM", x).put("yM", y).put("thetaRad", theta).put("vMps", 0.2)
                .put("wRadps", -0.1).put("leftMps", 0.21).put("rightMps", 0.19).build();
    }

    @Test
    void theDriversRecordBecomesAPoseAndAVelocity() {
        MethodHarness h = MethodHarness.started("odometry", new Odometry(OdometryParams.defaults()));
        h.push("odometry", odometry(1.5, -0.5, 3 * Math.PI / 2));
        RecordValue pose = (RecordValue) h.last("pose");
        assertThat(pose.number("xM")).isEqualTo(1.5);
        assertThat(pose.number("yM")).isEqualTo(-0.5);
        assertThat(pose.number("thetaRad")).as("wrapped into (-pi, pi]").isCloseTo(-Math.PI / 2, within(1e-12));
        assertThat(pose.has("leftMps")).isFalse();
        assertThat(h.last("velocity")).isEqualTo(VectorValue.of(0.2, -0.1));
    }

    @Test
    void fromTheFirstReadingThePoseIsRelativeToTheStart() {
        MethodHarness h = MethodHarness.started("odometry", new Odometry(new OdometryParams(true)));
        h.push("odometry", odometry(2.0, 1.0, Math.PI / 2));
        h.push("odometry", odometry(2.0, 2.0, Math.PI));
        RecordValue pose = (RecordValue) h.last("pose");
        assertThat(pose.number("xM")).as("one metre ahead of the start").isCloseTo(1.0, within(1e-12));
        assertThat(pose.number("yM")).isCloseTo(0.0, within(1e-12));
        assertThat(pose.number("thetaRad")).isCloseTo(Math.PI / 2, within(1e-12));
    }

    @Test
    void aRecordWithoutAPoseIsCountedAndNoVelocityWithoutSpeeds() {
        Odometry m = new Odometry(OdometryParams.defaults());
        MethodHarness h = MethodHarness.started("odometry", m);
        h.push("odometry", RecordValue.builder().put("xM", "here").build());
        h.push("odometry", RecordValue.builder().put("xM", 1.0).put("yM", 0.0).put("thetaRad", 0.0).build());
        assertThat(h.values("pose")).hasSize(1);
        assertThat(h.values("velocity")).isEmpty();
        assertThat(m.malformed()).isEqualTo(1);
    }
}
