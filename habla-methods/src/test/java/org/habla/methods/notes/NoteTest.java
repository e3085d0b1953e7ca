package org.habla.methods.notes;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import org.habla.config.ParamsJson;
import org.junit.jupiter.api.Test;

class NoteTest {

    @Test
    void namesAndFrequenciesFollowScientificPitchNotation() {
        assertThat(Note.parse("A4").midi()).isEqualTo(69);
        assertThat(Note.parse("C4").midi()).isEqualTo(60);
        assertThat(Note.parse("Bb3")).isEqualTo(Note.parse("A#3"));
        assertThat(Note.parse("c6").name()).isEqualTo("C6");
        assertThat(Note.parse("C5").frequency(440)).isCloseTo(523.25, within(0.01));
        assertThat(Note.parse("E5").frequency(440)).isCloseTo(659.25, within(0.01));
        assertThat(Note.parse("G5").frequency(440)).isCloseTo(783.99, within(0.01));
        assertThat(Note.parse("C6").frequency(440)).isCloseTo(1046.5, within(0.01));
        assertThat(Note.nearest(523.25 * 1.01, 440).name()).isEqualTo("C5");
        assertThat(Note.nearest(523.25 * 1.01, 440).centsFrom(523.25 * 1.01, 440)).isCloseTo(17.2, within(0.1));
    }

    @Test
    void aBadNameIsRefusedWithTheName() {
        assertThatThrownBy(() -> Note.parse("H2")).hasMessageContaining("'H2'");
        assertThatThrownBy(() -> Note.parse("C")).hasMessageContaining("not a note name");
        assertThatThrownBy(() -> ParamsJson.of(NoteRecognitionParams.class, "{\"notes\": [\"C5\", \"X9\"]}")).hasMessageContaining("'X9'");
    }
}
