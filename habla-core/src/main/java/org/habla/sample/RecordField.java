package org.habla.sample;

import java.util.Objects;

/**
 * One field of a record as people and control clients read about it: its JSON name, the kind of its JSON value,
 * its unit, what it is measured from or expressed in, and what it means.
 *
 * @param name     the JSON key ({@code "distanceM"})
 * @param type     the JSON value: {@code number}, {@code integer}, {@code boolean}, {@code text}, {@code array} or
 *                 {@code object}
 * @param unit     the unit of a number ({@code "m"}, {@code "rad"}), empty if none
 * @param frame    what the value is measured from or expressed in ({@code "robot frame: x forward, y left"},
 *                 {@code "the sensor"}), empty where no frame applies
 * @param doc      one sentence on the meaning
 * @param optional whether a record may leave the field out
 */
public record RecordField(String name, String type, String unit, String frame, String doc, boolean optional) {

    public RecordField {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(type, "type");
        unit = unit == null ? "" : unit;
        frame = frame == null ? "" : frame;
        doc = doc == null ? "" : doc;
    }

    /** The field as one line: {@code distanceM (number, m; from the sensor): the nearest reading}. */
    @Override
    public String toString() {
        StringBuilder s = new StringBuilder(name).append(" (").append(type);
        if (!unit.isEmpty()) {
            s.append(", ").append(unit);
        }
        if (optional) {
            s.append(", optional");
        }
        if (!frame.isEmpty()) {
            s.append("; ").append(frame);
        }
        s.append(')');
        return doc.isEmpty() ? s.toString() : s.append(": ").append(doc).toString();
    }
}
