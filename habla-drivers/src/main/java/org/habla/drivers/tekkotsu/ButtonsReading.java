package org.habla.drivers.tekkotsu;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code buttons} reading of an ERS-7: each button and touch sensor, by HABLA's name, in Tekkotsu's order.
 *
 * @param values each button's value, 0 (not touched) .. 1 (pressed), clamped to that range
 */
record ButtonsReading(Map<String, Double> values) implements RecordForm {

    static final RecordLayout<ButtonsReading> LAYOUT = RecordLayout.of(ButtonsReading.class)
            .entries("<button>", "number", ButtonsReading::values)
            .doc("each button's value, 0 (not touched) .. 1 (pressed)")
            .build();

    ButtonsReading {
        values = Collections.unmodifiableMap(new LinkedHashMap<>(values));
    }

    @Override
    public RecordLayout<ButtonsReading> layout() {
        return LAYOUT;
    }
}
