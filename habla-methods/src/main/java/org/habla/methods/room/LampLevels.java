package org.habla.methods.room;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code lamps} record of {@code room-action}: every lamp's level after the last action, one field per lamp.
 *
 * @param levels each lamp, in the config's order, and its level
 */
public record LampLevels(Map<String, Double> levels) implements RecordForm {

    /** The fields of a lamps record. */
    public static final RecordLayout<LampLevels> LAYOUT = RecordLayout.of(LampLevels.class)
            .entries("<lamp>", "number", LampLevels::levels).doc("each lamp's level, 0 (off) .. 1 (full)")
            .build();

    public LampLevels {
        levels = Collections.unmodifiableMap(new LinkedHashMap<>(levels));
    }

    @Override
    public RecordLayout<LampLevels> layout() {
        return LAYOUT;
    }
}
