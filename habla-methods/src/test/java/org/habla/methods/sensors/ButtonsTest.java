package org.habla.methods.sensors;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.habla.method.MethodHarness;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class ButtonsTest {

    private static RecordValue reading(double head, double back) {
        return RecordValue.builder().put("headTouch", head).put("backMiddle", back).put("chin", 0.0).build();
    }

    @Test
    void aPressIsNamedOnceOnItsEdgeAndPressedFollowsTheThresholds() {
        MethodHarness h = MethodHarness.started("buttons", new Buttons(ButtonsParams.defaults()));
        h.push("buttons", reading(0, 0));
        h.push("buttons", reading(0, 0.7));
        h.push("buttons", reading(0, 0.9));
        h.push("buttons", reading(0, 0.4));
        RecordValue held = (RecordValue) h.last("pressed");
        assertThat(held.get("backMiddle").booleanValue()).as("0.4 is above the release threshold 0.3").isTrue();
        assertThat(held.get("headTouch").booleanValue()).isFalse();
        h.push("buttons", reading(0.6, 0.1));
        h.push("buttons", reading(0.2, 0.8));
        assertThat(h.values("touch")).containsExactly(
                new TextValue("backMiddle"), new TextValue("headTouch"), new TextValue("backMiddle"));
        assertThat(h.values("pressed")).hasSize(6);
    }

    @Test
    void onlyTheNamedButtonsAreWatchedAndBadFieldsKeepTheirState() {
        MethodHarness h = MethodHarness.started("buttons", new Buttons(new ButtonsParams(0.8, 0.5, List.of("headTouch"))));
        h.push("buttons", reading(0.9, 1.0));
        h.push("buttons", RecordValue.builder().put("headTouch", "pressed").build());
        RecordValue p = (RecordValue) h.last("pressed");
        assertThat(p.get("headTouch").booleanValue()).isTrue();
        assertThat(p.has("backMiddle")).isFalse();
        h.push("buttons", reading(0.7, 0));
        h.push("buttons", reading(0.4, 0));
        h.push("buttons", reading(0.85, 0));
        assertThat(h.values("touch")).containsExactly(new TextValue("headTouch"), new TextValue("headTouch"));
    }

    /** Button values typed by a driver, which this module does not know: read field by field, as JSON would be. */
    record DriverButtons(Map<String, Double> values) implements RecordForm {
        static final RecordLayout<DriverButtons> LAYOUT = RecordLayout.of(DriverButtons.class)
                .entries("<button>", "number", DriverButtons::values).doc("each button's value").build();

        @Override
        public RecordLayout<DriverButtons> layout() {
            return LAYOUT;
        }
    }

    @Test
    void buttonValuesTypedByTheDriverAreReadByName() {
        Map<String, Double> values = new LinkedHashMap<>();
        values.put("chin", 1.0);
        values.put("headTouch", 0.25);
        MethodHarness all = MethodHarness.started("buttons", new Buttons(ButtonsParams.defaults()));
        all.push("buttons", RecordValue.of(new DriverButtons(values)));
        assertThat(((RecordValue) all.last("pressed")).jsonView().toString())
                .isEqualTo("{\"chin\":true,\"headTouch\":false}");
        MethodHarness named = MethodHarness.started("buttons", new Buttons(new ButtonsParams(0.8, 0.5, List.of("chin"))));
        named.push("buttons", RecordValue.of(new DriverButtons(values)));
        assertThat(named.values("touch")).containsExactly(new TextValue("chin"));
    }
}
