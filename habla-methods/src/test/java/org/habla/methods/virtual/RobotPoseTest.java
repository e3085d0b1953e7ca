package org.habla.methods.virtual;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.habla.method.MethodHarness;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

class RobotPoseTest {

    @Test
    void aPoseRecordIsHandedOnWithOnlyThePoseAndGarbageIsCounted() {
        RobotPose m = new RobotPose();
        MethodHarness h = MethodHarness.started("pose", m);
        h.push("pose", RecordValue.builder().put("xM", 0.5).put("yM", 1.0).put("thetaRad", -4.0).put("vMps", 0.1).build());
        RecordValue pose = (RecordValue) h.last("pose");
        assertThat(pose.json().size()).isEqualTo(3);
        assertThat(pose.number("xM")).isEqualTo(0.5);
        assertThat(pose.number("thetaRad")).isCloseTo(-4.0 + 2 * Math.PI, within(1e-12));
        h.push("pose", RecordValue.builder().put("xM", 0.5).put("yM", 1.0).build());
        assertThat(h.values("pose")).hasSize(1);
        assertThat(m.malformed()).isEqualTo(1);
    }
}
