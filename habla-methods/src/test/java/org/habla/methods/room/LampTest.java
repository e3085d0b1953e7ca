package org.habla.methods.room;

import static org.assertj.core.api.Assertions.assertThat;

import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

class LampTest {

    @Test
    void aDimmableLampGetsStateAndBrightnessAndZeroTurnsItOff() {
        MethodHarness h = MethodHarness.started("lamp", new Lamp(ParamsJson.of(Lamp.Params.class, "{}")));
        h.push("level", new NumberValue(0.5)).push("level", new NumberValue(0)).push("level", new NumberValue(7));
        assertThat(h.values("command")).containsExactly(
                RecordValue.builder().put("state", "ON").put("brightness", 127).build(),
                RecordValue.builder().put("state", "OFF").build(),
                RecordValue.builder().put("state", "ON").put("brightness", 254).build());
        assertThat(h.last("level")).isEqualTo(new NumberValue(1));
    }

    @Test
    void aRepeatedLevelSendsNothingNew() {
        MethodHarness h = MethodHarness.started("lamp", new Lamp(ParamsJson.of(Lamp.Params.class, "{}")));
        h.push("level", new NumberValue(1)).push("level", new NumberValue(1)).push("level", new NumberValue(0.999));
        assertThat(h.values("command")).hasSize(1);
    }

    @Test
    void aPlainLampSwitchesAtItsThreshold() {
        MethodHarness h = MethodHarness.started("lamp", new Lamp(ParamsJson.of(Lamp.Params.class, "{\"dimmable\": false, \"onAbove\": 0.3}")));
        h.push("level", new NumberValue(0.2)).push("level", new NumberValue(0.4));
        assertThat(h.values("command")).containsExactly(RecordValue.builder().put("state", "OFF").build(),
                RecordValue.builder().put("state", "ON").build());
    }
    @Test
    void aLevelTheLampNeverConfirmedIsSentAgainOnceResendMsHasPassed() {
        MethodHarness h = MethodHarness.started("lamp", new Lamp(ParamsJson.of(Lamp.Params.class, "{\"resendMs\": 500}")));
        h.push("level", new NumberValue(0.8)).advanceMillis(499).push("level", new NumberValue(0.8));
        assertThat(h.values("command")).as("a controller repeating itself does not flood the broker").hasSize(1);
        h.advanceMillis(2).push("level", new NumberValue(0.8));
        assertThat(h.values("command")).hasSize(2);
    }

    @Test
    void aCommandSentWhileTheLampCouldNotBeReachedIsSentAgainAsSoonAsItCan() {
        MethodHarness h = MethodHarness.started("lamp", new Lamp(ParamsJson.of(Lamp.Params.class, "{}")));
        h.stale(true).push("level", new NumberValue(0.8));
        h.stale(false).push("level", new NumberValue(0.8));
        assertThat(h.values("command")).hasSize(2);
        h.push("level", new NumberValue(0.8));
        assertThat(h.values("command")).hasSize(2);
    }

    @Test
    void theLampsOwnStateDecidesWhetherACommandIsNeededSoAWallSwitchIsSeen() {
        MethodHarness h = MethodHarness.started("lamp", new Lamp(ParamsJson.of(Lamp.Params.class, "{}")));
        h.push("level", new NumberValue(0.8));
        RecordValue on = RecordValue.builder().put("state", "ON").put("brightness", 203).put("linkquality", 140).build();
        h.push("state", on);
        assertThat(h.last("reported")).isEqualTo(new NumberValue(203 / 254.0));
        h.advanceMillis(60_000).push("level", new NumberValue(0.8));
        assertThat(h.values("command")).as("the lamp said it does this already").hasSize(1);
        h.push("state", RecordValue.builder().put("state", "OFF").put("brightness", 0).build());
        assertThat(h.last("reported")).isEqualTo(new NumberValue(0));
        h.push("level", new NumberValue(0.8));
        assertThat(h.values("command")).as("switched off at the wall: sent again").hasSize(2);
    }

    @Test
    void theCommandsAreWrittenInTheZigbeeLightSchema() {
        MethodHarness dimmable = MethodHarness.started("lamp", new Lamp(ParamsJson.of(Lamp.Params.class, "{}")));
        dimmable.push("level", new NumberValue(0.5)).push("level", new NumberValue(0));
        MethodHarness plain = MethodHarness.started("lamp",
                new Lamp(ParamsJson.of(Lamp.Params.class, "{\"dimmable\": false}")));
        plain.push("level", new NumberValue(1));
        assertThat(dimmable.values("command")).extracting(v -> ((RecordValue) v).jsonView().toString())
                .containsExactly("{\"state\":\"ON\",\"brightness\":127}", "{\"state\":\"OFF\"}");
        assertThat(plain.values("command")).extracting(v -> ((RecordValue) v).jsonView().toString())
                .containsExactly("{\"state\":\"ON\"}");
        assertThat(((RecordValue) dimmable.last("command")).form(LampCommand.class)).as("typed inside the daemon")
                .contains(LampCommand.OFF);
    }
}
