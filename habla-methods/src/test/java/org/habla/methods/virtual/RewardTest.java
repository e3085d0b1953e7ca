package org.habla.methods.virtual;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Map;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class RewardTest {

    private static RecordValue buttons(double headTouch, double backMiddle) {
        return RecordValue.builder().put("headTouch", headTouch).put("backFront", 0.0).put("backMiddle", backMiddle)
                .put("backRear", 0.0).build();
    }

    @Test
    void numbersAndWordsBecomeRewardsAndOtherTextIsCounted() {
        Reward m = new Reward(RewardParams.defaults());
        MethodHarness h = MethodHarness.started("reward", m);
        for (String line : new String[] {"+1", "-0.5", " PAIN ", "pleasure", "+7", "hello", "1e400", "", "Good  Dog"}) {
            h.push("text", new TextValue(line));
        }
        assertThat(h.values("reward")).containsExactly(new NumberValue(1), new NumberValue(-0.5), new NumberValue(-1),
                new NumberValue(1), new NumberValue(1), new NumberValue(1));
        assertThat(m.ignored()).isEqualTo(3);
    }

    @Test
    void aTouchGivesOneRewardPerPressNotWhileHeld() {
        MethodHarness h = MethodHarness.started("reward", new Reward(RewardParams.defaults()));
        h.push("buttons", buttons(0, 0));
        h.push("buttons", buttons(0, 0.9));
        h.push("buttons", buttons(0, 1.0));
        h.push("buttons", buttons(0, 0.1));
        h.push("buttons", buttons(0.8, 0));
        h.push("buttons", buttons(0, 0.6));
        assertThat(h.values("reward")).containsExactly(new NumberValue(1), new NumberValue(-1), new NumberValue(1));
    }

    @Test
    void touchMapAndThresholdComeFromParamsAndBooleansCount() {
        MethodHarness h = MethodHarness.started("reward",
                new Reward(ParamsJson.of(RewardParams.class, "{\"touch\": {\"chin\": 0.5}, \"threshold\": 0.2}")));
        h.push("buttons", RecordValue.builder().put("chin", 0.3).build());
        h.push("buttons", RecordValue.builder().put("chin", false).build());
        h.push("buttons", RecordValue.builder().put("chin", true).build());
        h.push("buttons", RecordValue.builder().put("chin", "pressed").build());
        assertThat(h.values("reward")).containsExactly(new NumberValue(0.5), new NumberValue(0.5));
    }

    @Test
    void aRewardOutsideTheRangeIsRefused() {
        assertThatThrownBy(() -> ParamsJson.of(RewardParams.class, "{\"words\": {\"yay\": 2.0}}")).hasMessageContaining("words entry 'yay'");
    }
}
