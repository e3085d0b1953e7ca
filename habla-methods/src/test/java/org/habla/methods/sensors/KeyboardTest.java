package org.habla.methods.sensors;

import static org.assertj.core.api.Assertions.assertThat;

import org.habla.method.MethodHarness;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class KeyboardTest {

    @Test
    void linesAreTrimmedFreedOfControlCharactersAndCut() {
        Keyboard k = new Keyboard(new KeyboardParams(8));
        MethodHarness h = MethodHarness.started("keyboard", k);
        for (String line : new String[] {"  +1 \r", "\u0007pa\tin\u0000", " \u001b[A ", "", "good  dog\nand more"}) {
            h.push("line", new TextValue(line));
        }
        assertThat(h.values("line")).containsExactly(new TextValue("+1"), new TextValue("pa in"),
                new TextValue("[A"), new TextValue("good dog"));
        assertThat(k.dropped()).isEqualTo(1);
        assertThat(k.cut()).isEqualTo(1);
    }
}
