package org.habla.methods.room;

import static org.assertj.core.api.Assertions.assertThat;

import org.habla.method.MethodHarness;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

class LampTest {

    @Test
    void aDimmableLampGetsStateAndBrightnessAndZeroTurnsItOff() {
        MethodHarness h = MethodHarness.started("lamp", new Lamp(new Lamp.Params(null, null, null)));
        h.push("level", new NumberValue(0.5)).push("level", new NumberValue(0)).push("level", new NumberValue(7));
        assertThat(h.values("command")).containsExactly(
                RecordValue.builder().put("state", "ON").put("brightness", 127).build(),
                RecordValue.builder().put("state", "OFF").build(),
                RecordValue.builder().put("state", "ON").put("brightness", 254).build());
        assertThat(h.last("level")).isEqualTo(new NumberValue(1));
    }

    @Test
    void aRepeatedLevelSendsNothingNew() {
        MethodHarness h = MethodHarness.started("lamp", new Lamp(new Lamp.Params(null, null, null)));
        h.push("level", new NumberValue(1)).push("level", new NumberValue(1)).push("level", new NumberValue(0.999));
        assertThat(h.values("command")).hasSize(1);
    }

    @Test
    void aPlainLampSwitchesAtItsThreshold() {
        MethodHarness h = MethodHarness.started("lamp", new Lamp(new Lamp.Params(false, null, 0.3)));
        h.push("level", new NumberValue(0.2)).push("level", new NumberValue(0.4));
        assertThat(h.values("command")).containsExactly(RecordValue.builder().put("state", "OFF").build(),
                RecordValue.builder().put("state", "ON").build());
    }
}
