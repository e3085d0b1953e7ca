package org.habla.methods.actuators;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.MethodHarness;
import org.habla.methods.motion.MotionLimits;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class WheelsTest {

    private static ChannelDescriptor motionChannel() throws Exception {
        ObjectNode geometry = (ObjectNode) new ObjectMapper().readTree(
                "{\"radiusM\":0.26,\"widthM\":0.38,\"lengthM\":0.44,\"maxVelMps\":0.5,\"maxRotVelRadps\":1.0}");
        return ChannelDescriptor.command("motion", PayloadKind.VECTOR, "m/s, rad/s", true).withMetadata(geometry);
    }

    @Test
    void aMotionWithinTheLimitsGoesOutUnchangedAndOneBeyondIsScaledKeepingItsCurvature() throws Exception {
        MethodHarness h = MethodHarness.of("wheels", new Wheels(WheelsParams.defaults()))
                .wireCommand("motion", motionChannel()).start();
        h.push("motion", VectorValue.of(0.2, -0.3));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0.2, -0.3));
        h.push("motion", VectorValue.of(1.0, 1.0));
        VectorValue scaled = (VectorValue) h.last("motion");
        assertThat(scaled.get(0)).isCloseTo(0.5, within(1e-12));
        assertThat(scaled.get(1)).isCloseTo(0.5, within(1e-12));
        h.push("motion", VectorValue.of(0.1, -4.0));
        scaled = (VectorValue) h.last("motion");
        assertThat(scaled.get(1)).isCloseTo(-1.0, within(1e-12));
        assertThat(scaled.get(0) / scaled.get(1)).isCloseTo(0.1 / -4.0, within(1e-12));
    }

    @Test
    void paramsOverrideTheChannelAndTheLimitsArePublished() throws Exception {
        MethodHarness h = MethodHarness.of("wheels", new Wheels(new WheelsParams(0.3, null)))
                .wireCommand("motion", motionChannel()).start();
        assertThat(h.last("limits")).isEqualTo(RecordValue.builder().put("maxVelMps", 0.3).put("maxRotVelRadps", 1.0).build());
        h.push("motion", VectorValue.of(-0.6, 0));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(-0.3, 0));
        h.advanceMillis(2100);
        assertThat(h.values("limits")).hasSize(3);
    }

    @Test
    void garbageBecomesZeroAndStoppingSendsZero() {
        Wheels w = new Wheels(WheelsParams.defaults());
        MethodHarness h = MethodHarness.started("wheels", w);
        assertThat(w.limits()).isEqualTo(MotionLimits.NONE);
        h.push("motion", VectorValue.of(3.0, 0.0));
        assertThat(h.last("motion")).as("no limits known: unscaled").isEqualTo(VectorValue.of(3.0, 0.0));
        h.push("motion", VectorValue.of(0.2, Double.NaN));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, 0));
        h.push("motion", VectorValue.of(0.2, 0.1, 0.0));
        assertThat(w.malformed()).isEqualTo(2);
        h.push("motion", VectorValue.of(0.2, 0.1));
        h.stop();
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, 0));
    }
}
