package org.habla.methods.sensors;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.habla.config.ParamsJson;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.MethodHarness;
import org.habla.method.MethodState;
import org.habla.sample.PayloadKind;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class LegsTest {

    @Test
    void eachComponentIsClampedToItsOwnLimit() {
        MethodHarness h = MethodHarness.started("legs", new Legs(LegsParams.defaults()));
        h.push("walk", VectorValue.of(0.1, -0.05, 0.5));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(0.1, -0.05, 0.5));
        h.push("walk", VectorValue.of(0.5, 0.3, -4.0));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(0.18, 0.14, -1.8));
        h.push("walk", VectorValue.of(-0.5, 0, 0));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(-0.18, 0, 0));
    }

    @Test
    void limitsComeFromParamsAndATwoElementVectorIsForwardAndRotate() {
        MethodHarness h = MethodHarness.started("legs", new Legs(ParamsJson.of(LegsParams.class, "{\"maxForwardMps\": 0.3, \"maxReverseMps\": 0.1, \"maxStrafeMps\": 0.0, \"maxRotateRadps\": 1.0}")));
        h.push("walk", VectorValue.of(0.25, 2.0));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(0.25, 0, 1.0));
        h.push("walk", VectorValue.of(-0.25, 0.2, 0));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(-0.1, 0, 0));
    }

    @Test
    void limitsLeftOutComeFromTheWalkChannelsMetadata() {
        ObjectNode meta = JsonNodeFactory.instance.objectNode().put("maxForwardMps", 0.25).put("maxReverseMps", 0.05)
                .put("maxStrafeMps", 0.1).put("maxRotateRadps", 0.9);
        ChannelDescriptor walk = ChannelDescriptor.command("walk", PayloadKind.VECTOR, "m/s, rad/s", true).withMetadata(meta);
        Legs legs = new Legs(ParamsJson.of(LegsParams.class, "{\"maxStrafeMps\": 0.02}"));
        MethodHarness h = MethodHarness.of("legs", legs).wireCommand("walk", walk).start();
        h.push("walk", VectorValue.of(1, 1, 1));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(0.25, 0.02, 0.9));
        h.push("walk", VectorValue.of(-1, -1, -1));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(-0.05, -0.02, -0.9));
    }

    @Test
    void aBadCommandStopsTheRobotAndStoppingTheMethodSendsZero() {
        Legs legs = new Legs(LegsParams.defaults());
        MethodHarness h = MethodHarness.started("legs", legs);
        h.push("walk", VectorValue.of(0.1, 0, 0));
        h.push("walk", VectorValue.of(Double.NaN, 0, 0));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(0, 0, 0));
        h.push("walk", VectorValue.of(0.1, 0, 0, 0));
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(0, 0, 0));
        assertThat(legs.rejected()).isEqualTo(2);
        h.push("walk", VectorValue.of(0.1, 0, 0));
        assertThat(h.state()).isEqualTo(MethodState.RUNNING);
        h.stop();
        assertThat(h.values("walk")).hasSize(5);
        assertThat(h.last("walk")).isEqualTo(VectorValue.of(0, 0, 0));
    }
}
