package org.habla.methods.room;

import java.util.Objects;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code command} record of {@code room-speaker}: what a networked speaker that speaks text itself is to say,
 * and how loud, {@code {"say": text, "volume": 0..100}}.
 *
 * @param say    the text to say
 * @param volume the speaker's volume, 0..100 percent
 */
public record SpeakerCommand(String say, int volume) implements RecordForm {

    /** The fields of a speaker command. */
    public static final RecordLayout<SpeakerCommand> LAYOUT = RecordLayout.of(SpeakerCommand.class)
            .text("say", SpeakerCommand::say).doc("the text to say")
            .longInteger("volume", SpeakerCommand::volume).unit("%").doc("how loud, 0..100")
            .build();

    public SpeakerCommand {
        Objects.requireNonNull(say, "say");
        if (volume < 0 || volume > 100) {
            throw new IllegalArgumentException("a speaker's volume is 0..100 percent, was " + volume);
        }
    }

    @Override
    public RecordLayout<SpeakerCommand> layout() {
        return LAYOUT;
    }
}
