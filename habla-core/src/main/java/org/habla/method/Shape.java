package org.habla.method;

import java.util.List;
import java.util.Objects;
import org.habla.driver.ChannelDescriptor;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordField;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * What the values of a port look like, for people and for control clients: the payload kind, a unit, and for
 * records the fields (each with its unit, meaning and frame when a {@link RecordLayout} declares them), for
 * vectors the element names or length.
 *
 * @param kind     the payload kind
 * @param unit     the unit of numbers and vector elements ({@code "m"}, {@code "rad"}, {@code ""} if none)
 * @param fields   record field names, or vector element names; empty if not fixed
 * @param doc      one sentence on the meaning
 * @param layout   for a record port, the typed value it carries inside the daemon and its declared fields, or null
 * @param passesOn the input whose values this output hands on as they come, or null: the output then looks like
 *                 whatever feeds that input (the shape of a {@code pass-through})
 */
public record Shape(PayloadKind kind, String unit, List<String> fields, String doc, RecordLayout<?> layout,
        String passesOn) {

    public Shape {
        Objects.requireNonNull(kind, "kind");
        unit = unit == null ? "" : unit;
        fields = List.copyOf(fields == null ? List.of() : fields);
        doc = doc == null ? "" : doc;
        if (layout != null && kind != PayloadKind.RECORD) {
            throw new IllegalArgumentException("only a record port carries a record form, not a " + kind + " port");
        }
    }

    public Shape(PayloadKind kind, String unit, List<String> fields, String doc) {
        this(kind, unit, fields, doc, null, null);
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

    /** A record port whose values are plain JSON with these fields (a device's own message, say). */
    public static Shape record(String doc, String... fields) {
        return new Shape(PayloadKind.RECORD, "", List.of(fields), doc);
    }

    /** A record port that carries the form {@code layout} describes; its fields are the layout's. */
    public static Shape record(String doc, RecordLayout<?> layout) {
        return new Shape(PayloadKind.RECORD, "", layout.names(), doc, layout, null);
    }

    /**
     * An output of kind {@code kind} that hands on what input {@code input} receives: where the graph knows what
     * feeds that input, the output is shown with that source's shape.
     */
    public static Shape passedOn(PayloadKind kind, String input) {
        return new Shape(kind, "", List.of(), "what input " + input + " receives, handed on", null,
                Objects.requireNonNull(input, "input"));
    }

    /** The shape of the values of an interface channel: its kind, unit and, for a record channel, its layout. */
    public static Shape of(ChannelDescriptor channel) {
        RecordLayout<?> layout = channel.layout();
        return new Shape(channel.kind(), channel.unit(), layout == null ? List.of() : layout.names(),
                "channel " + channel.name(), layout, null);
    }

    /** The typed value a record port carries inside the daemon, or null. */
    public Class<? extends RecordForm> form() {
        return layout == null ? null : layout.form();
    }

    /** The declared fields of a record port, each with unit, meaning and frame; empty when none are declared. */
    public List<RecordField> recordFields() {
        return layout == null ? List.of() : layout.fields();
    }

    /** Whether a typed record value may leave a port of this shape: any value if it names no form, else its form. */
    public boolean admits(Payload value) {
        return layout == null || !(value instanceof RecordValue r) || r.carriesForm() == null
                || layout.form().isInstance(r.carriesForm());
    }
}
