package org.habla.methods.room;

import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code command} record of {@code blinds}: where a cover is to go, as Zigbee2MQTT and Home Assistant take it,
 * {@code {"position": 0..100}}.
 *
 * @param position percent open, or percent closed for a cover that counts that way (the method's {@code invert})
 */
public record CoverCommand(int position) implements RecordForm {

    /** The fields of a cover command. */
    public static final RecordLayout<CoverCommand> LAYOUT = RecordLayout.of(CoverCommand.class)
            .longInteger("position", CoverCommand::position).unit("%")
            .doc("how far the cover is to be open, 0..100 (closed, for a cover that counts closed)")
            .build();

    public CoverCommand {
        if (position < 0 || position > 100) {
            throw new IllegalArgumentException("a cover's position is 0..100 percent, was " + position);
        }
    }

    @Override
    public RecordLayout<CoverCommand> layout() {
        return LAYOUT;
    }
}
