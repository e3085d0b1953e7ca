package org.habla.methods.sensors;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code pressed} record of {@code buttons}: one field per watched button, true while it is held down.
 *
 * @param pressed each button, in the order the readings or the params name them, and whether it is down
 */
public record ButtonStates(Map<String, Boolean> pressed) implements RecordForm {

    /** The fields of a pressed record. */
    public static final RecordLayout<ButtonStates> LAYOUT = RecordLayout.of(ButtonStates.class)
            .entries("<button>", "boolean", ButtonStates::pressed).doc("each button: true while it is held down")
            .build();

    public ButtonStates {
        pressed = Collections.unmodifiableMap(new LinkedHashMap<>(pressed));
    }

    @Override
    public RecordLayout<ButtonStates> layout() {
        return LAYOUT;
    }
}
