package org.habla.methods.virtual;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class ActionTest {

    private static MethodHarness action() {
        return MethodHarness.started("action", new Action(ActionParams.defaults()));
    }

    @Test
    void forwardIsHeldForTheDurationThenZeroed() {
        MethodHarness h = action();
        h.write("action", new TextValue("forward"));
        assertThat(h.values("motion")).containsExactly(VectorValue.of(0.2, 0));
        h.advanceMillis(960);
        assertThat(h.values("motion")).hasSize(1);
        h.advanceMillis(60);
        assertThat(h.values("motion")).containsExactly(VectorValue.of(0.2, 0), VectorValue.of(0, 0));
        h.advanceMillis(2000);
        assertThat(h.values("motion")).as("zero is sent once").hasSize(2);
    }

    @Test
    void eachLabelHasItsSignedMotionAndIsEchoed() {
        MethodHarness h = MethodHarness.started("action", new Action(ParamsJson.of(ActionParams.class, "{\"forwardMps\": 0.3, \"backMps\": 0.1, \"turnRadps\": 0.5, \"durationMs\": 500}")));
        for (String label : new String[] {"left", "right", " BACK\n", "forward"}) {
            h.write("action", new TextValue(label));
        }
        assertThat(h.values("motion")).containsExactly(VectorValue.of(0, 0.5), VectorValue.of(0, -0.5),
                VectorValue.of(-0.1, 0), VectorValue.of(0.3, 0));
        assertThat(h.values("action")).containsExactly(new TextValue("left"), new TextValue("right"),
                new TextValue("back"), new TextValue("forward"));
    }

    @Test
    void stopZerosAtOnceAndNothingFollows() {
        MethodHarness h = action();
        h.write("action", new TextValue("left")).advanceMillis(300).write("action", new TextValue("stop"));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, 0));
        h.advanceMillis(3000);
        assertThat(h.values("motion")).hasSize(2);
        assertThat(h.last("action")).isEqualTo(new TextValue("stop"));
    }

    @Test
    void aNewLabelRestartsTheHold() {
        MethodHarness h = action();
        h.write("action", new TextValue("forward")).advanceMillis(800).write("action", new TextValue("right"));
        h.advanceMillis(800);
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, -0.6));
        h.advanceMillis(300);
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, 0));
    }

    @Test
    void aMotionStopDropsTheHeldLabelAndSaysZeroAtOnce() {
        MethodHarness h = action();
        h.write("action", new TextValue("left")).advanceMillis(300).motionStopped();
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, 0));
        h.advanceMillis(3000).motionStopped();
        assertThat(h.values("motion")).as("nothing more: no hold left to end, nothing to zero again").hasSize(2);
        h.write("action", new TextValue("left"));
        assertThat(h.last("motion")).isEqualTo(VectorValue.of(0, 0.6));
    }

    @Test
    void anUnknownLabelIsRefusedNamingTheActionsAndChangesNothing() {
        MethodHarness h = action();
        assertThatThrownBy(() -> h.write("action", new TextValue("jump")))
                .hasMessageContaining("unknown action 'jump'")
                .hasMessageContaining("forward, left, right, back, stop");
        assertThat(h.values("motion")).isEmpty();
        h.push("action", new TextValue("fly"));
        assertThat(h.values("action")).isEmpty();
        assertThat(h.state()).isEqualTo(org.habla.method.MethodState.RUNNING);
    }

    @Test
    void paramsOutOfRangeNameTheParameter() {
        assertThatThrownBy(() -> ParamsJson.of(ActionParams.class, "{\"forwardMps\": -1.0}")).hasMessageContaining("forwardMps");
        assertThatThrownBy(() -> ParamsJson.of(ActionParams.class, "{\"durationMs\": 0}")).hasMessageContaining("durationMs");
    }
}
