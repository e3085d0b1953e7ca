package org.habla.method;

import java.util.List;
import java.util.Objects;
import org.habla.sample.PayloadKind;

/**
 * What the values of a port look like, for people and for control clients: the payload kind,
 * a unit, and for records the field names, for vectors the element names or length.
 *
 * @param kind   the payload kind
 * @param unit   the unit of numbers and vector elements ({@code "m"}, {@code "rad"}, {@code ""} if none)
 * @param fields record field names, or vector element names; empty if not fixed
 * @param doc    one sentence on the meaning
 */
public record Shape(PayloadKind kind, String unit, List<String> fields, String doc) {

    public Shape {
        Objects.requireNonNull(kind, "kind");
        unit = unit == null ? "" : unit;
        fields = List.copyOf(fields == null ? List.of() : fields);
        doc = doc == null ? "" : doc;
    }

    public static Shape of(PayloadKind kind) {
        return new Shape(kind, "", List.of(), "");
    }

    public static Shape number(String unit, String doc) {
        return new Shape(PayloadKind.NUMBER, unit, List.of(), doc);
    }

    public static Shape text(String doc) {
        return new Shape(PayloadKind.TEXT, "", List.of(), doc);
    }

    public static Shape vector(String unit, String doc) {
        return new Shape(PayloadKind.VECTOR, unit, List.of(), doc);
    }

    public static Shape record(String doc, String... fields) {
        return new Shape(PayloadKind.RECORD, "", List.of(fields), doc);
    }
}
