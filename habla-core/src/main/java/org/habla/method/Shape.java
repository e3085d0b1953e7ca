package org.habla.method;

import java.util.List;
import java.util.Objects;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordValue;

/**
 * What the values of a port look like, for people and for control clients: the payload kind,
 * a unit, and for records the field names, for vectors the element names or length.
 *
 * @param kind   the payload kind
 * @param unit   the unit of numbers and vector elements ({@code "m"}, {@code "rad"}, {@code ""} if none)
 * @param fields record field names, or vector element names; empty if not fixed
 * @param doc    one sentence on the meaning
 * @param form   for a record port, the typed value it carries inside the daemon ({@link RecordForm}), or null
 */
public record Shape(PayloadKind kind, String unit, List<String> fields, String doc,
        Class<? extends RecordForm> form) {

    public Shape {
        Objects.requireNonNull(kind, "kind");
        unit = unit == null ? "" : unit;
        fields = List.copyOf(fields == null ? List.of() : fields);
        doc = doc == null ? "" : doc;
        if (form != null && kind != PayloadKind.RECORD) {
            throw new IllegalArgumentException("only a record port carries a record form, not a " + kind + " port");
        }
    }

    public Shape(PayloadKind kind, String unit, List<String> fields, String doc) {
        this(kind, unit, fields, doc, null);
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

    /**
     * A record port that carries {@code form} inside the daemon; its fields are the ones the form's
     * {@link RecordForm.Fields} names (an optional one without its {@code ?}).
     *
     * @throws IllegalArgumentException if the form does not name its fields
     */
    public static Shape record(String doc, Class<? extends RecordForm> form) {
        return new Shape(PayloadKind.RECORD, "", fieldsOf(form), doc, form);
    }

    /** The JSON fields {@code form} names, optional ones without their {@code ?}. */
    public static List<String> fieldsOf(Class<? extends RecordForm> form) {
        RecordForm.Fields named = form.getAnnotation(RecordForm.Fields.class);
        if (named == null || named.value().length == 0) {
            throw new IllegalArgumentException(form.getSimpleName() + " is a record form without @RecordForm.Fields");
        }
        return java.util.Arrays.stream(named.value()).map(f -> f.endsWith("?") ? f.substring(0, f.length() - 1) : f)
                .toList();
    }

    /** Whether a typed record value may leave a port of this shape: any value if it names no form, else its form. */
    public boolean admits(Payload value) {
        return form == null || !(value instanceof RecordValue r) || r.carriesForm() == null
                || form.isInstance(r.carriesForm());
    }
}
