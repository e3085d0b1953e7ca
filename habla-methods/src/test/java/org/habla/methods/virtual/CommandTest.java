package org.habla.methods.virtual;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Map;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class CommandTest {

    @Test
    void notesAndPhrasesBecomeLabelsAndTheRestIsCounted() {
        Command m = new Command(CommandParams.defaults());
        MethodHarness h = MethodHarness.started("command", m);
        for (String heard : new String[] {"C5", "  Turn   LEFT ", "A4", "g5", "good dog", "go back"}) {
            h.push("in", new TextValue(heard));
        }
        assertThat(h.values("command")).containsExactly(new TextValue("forward"), new TextValue("left"),
                new TextValue("right"), new TextValue("back"));
        assertThat(m.ignored()).isEqualTo(2);
    }

    @Test
    void aRepeatWithinTheDebounceIsDroppedButADifferentLabelIsNot() {
        Command m = new Command(ParamsJson.of(CommandParams.class, "{\"map\": {\"do\": \"forward\", \"re\": \"left\"}, \"debounceMs\": 500}"));
        MethodHarness h = MethodHarness.started("command", m);
        h.push("in", new TextValue("do")).advanceMillis(200).push("in", new TextValue("do"));
        h.push("in", new TextValue("re")).advanceMillis(100).push("in", new TextValue("do"));
        h.advanceMillis(600).push("in", new TextValue("do"));
        assertThat(h.values("command")).containsExactly(new TextValue("forward"), new TextValue("left"),
                new TextValue("forward"), new TextValue("forward"));
        assertThat(m.debounced()).isEqualTo(1);
    }

    @Test
    void aMapWithABlankLabelIsRefused() {
        assertThatThrownBy(() -> ParamsJson.of(CommandParams.class, "{\"map\": {\"C5\": \" \"}}")).hasMessageContaining("map entry 'C5'");
        assertThatThrownBy(() -> ParamsJson.of(CommandParams.class, "{\"map\": {}}")).hasMessageContaining("map must hold");
    }
}
