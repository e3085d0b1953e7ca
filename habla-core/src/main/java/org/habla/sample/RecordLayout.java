package org.habla.sample;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Function;
import java.util.function.Predicate;
import java.util.function.ToDoubleFunction;
import java.util.function.ToIntFunction;
import java.util.function.ToLongFunction;

/**
 * The fields of a {@link RecordForm}, declared once, beside the type: each field's JSON name, unit, meaning and
 * frame, in the order the record's JSON has them, and how to read it from the Java value. From it come the
 * record's JSON at an edge ({@link #json}), its fields without any JSON (what {@link RecordValue#number} and the
 * other accessors read), and what {@code habla plugins}, a socket's hello and the monitor say about the fields.
 *
 * <pre>{@code
 * static final RecordLayout<Obstacle> LAYOUT = RecordLayout.of(Obstacle.class)
 *         .number("distanceM", Obstacle::distanceM).unit("m").frame("from the sensor").doc("the nearest reading")
 *         .flag("valid", Obstacle::valid).doc("false when nothing was seen")
 *         .build();
 * }</pre>
 *
 * A field's value is a {@code Double}, {@code Integer}, {@code Long}, {@code Boolean}, {@code String} or, for an
 * array or object, a {@link JsonNode} made when asked; a field whose value is null is left out of the record.
 *
 * @param <F> the form
 */
public final class RecordLayout<F extends RecordForm> {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private final Class<F> form;
    private final List<RecordField> fields;
    private final List<Function<F, Object>> values;
    /** For each field, whether it stands for entries named at run time (a map written field by field). */
    private final List<Boolean> entries;
    private final Map<String, Integer> index;

    private RecordLayout(Class<F> form, List<RecordField> fields, List<Function<F, Object>> values,
            List<Boolean> entries) {
        this.form = form;
        this.fields = List.copyOf(fields);
        this.values = List.copyOf(values);
        this.entries = List.copyOf(entries);
        Map<String, Integer> byName = new LinkedHashMap<>();
        for (int i = 0; i < fields.size(); i++) {
            if (!entries.get(i) && byName.put(fields.get(i).name(), i) != null) {
                throw new IllegalArgumentException(form.getSimpleName() + " declares field " + fields.get(i).name()
                        + " twice");
            }
        }
        this.index = java.util.Collections.unmodifiableMap(byName);
    }

    /** Starts the layout of {@code form}. */
    public static <F extends RecordForm> Builder<F> of(Class<F> form) {
        return new Builder<>(form);
    }

    /** The Java type of the records this layout describes. */
    public Class<F> form() {
        return form;
    }

    /** The fields, in the order the JSON has them. */
    public List<RecordField> fields() {
        return fields;
    }

    /** The names of the fixed fields, in order (fields named at run time are not among them). */
    public List<String> names() {
        return List.copyOf(index.keySet());
    }

    /** The record as JSON, field by field in declared order, leaving out the fields whose value is null. */
    public ObjectNode json(RecordForm value) {
        F f = form.cast(value);
        ObjectNode o = NODES.objectNode();
        for (int i = 0; i < fields.size(); i++) {
            Object v = values.get(i).apply(f);
            if (v instanceof Map<?, ?> each && entries.get(i)) {
                each.forEach((name, x) -> o.set((String) name, RecordJson.node(x)));
            } else if (v != null) {
                o.set(fields.get(i).name(), RecordJson.node(v));
            }
        }
        return o;
    }

    /** Writes {@link #json}'s object straight to {@code g}, without making it; false, writing nothing, if it cannot. */
    public boolean write(RecordForm value, JsonGenerator g) throws IOException {
        F f = form.cast(value);
        return RecordJson.write(fields, entries, index.keySet(), values.stream().map(v -> v.apply(f)).toArray(), g);
    }

    /** The value of field {@code name} of {@code value} (see the class comment), or null when it has none. */
    Object value(RecordForm value, String name) {
        F f = form.cast(value);
        Integer i = index.get(name);
        if (i != null) {
            return values.get(i).apply(f);
        }
        for (int k = 0; k < fields.size(); k++) {
            if (entries.get(k) && values.get(k).apply(f) instanceof Map<?, ?> each && each.containsKey(name)) {
                return each.get(name);
            }
        }
        return null;
    }

    /** A hash that a record's JSON gives too ({@link RecordHash}): equal records hash alike, typed or not. */
    int hash(RecordForm value) {
        F f = form.cast(value);
        int h = 0;
        for (int i = 0; i < fields.size(); i++) {
            Object v = values.get(i).apply(f);
            if (v instanceof Map<?, ?> each && entries.get(i)) {
                for (Map.Entry<?, ?> e : each.entrySet()) {
                    h += RecordHash.of((String) e.getKey(), e.getValue());
                }
            } else if (v != null) {
                h += RecordHash.of(fields.get(i).name(), v);
            }
        }
        return h;
    }

    @Override
    public String toString() {
        return form.getSimpleName() + names();
    }

    /**
     * Declares a layout field by field; {@link #unit}, {@link #frame}, {@link #doc} and {@link #optional} describe
     * the field declared last.
     */
    public static final class Builder<F extends RecordForm> {
        private final Class<F> form;
        private final List<RecordField> fields = new ArrayList<>();
        private final List<Function<F, Object>> values = new ArrayList<>();
        private final List<Boolean> entries = new ArrayList<>();

        private Builder(Class<F> form) {
            this.form = Objects.requireNonNull(form, "form");
        }

        /** A number, written as a double. */
        public Builder<F> number(String name, ToDoubleFunction<F> value) {
            return field(name, "number", f -> value.applyAsDouble(f));
        }

        /** A number that a record may lack: null leaves it out. */
        public Builder<F> optionalNumber(String name, Function<F, Double> value) {
            return field(name, "number", value::apply).optional();
        }

        /** A whole number, written as an int. */
        public Builder<F> integer(String name, ToIntFunction<F> value) {
            return field(name, "integer", f -> value.applyAsInt(f));
        }

        /** A whole number, written as a long. */
        public Builder<F> longInteger(String name, ToLongFunction<F> value) {
            return field(name, "integer", f -> value.applyAsLong(f));
        }

        /** A whole number that a record may lack, written as a long: null leaves it out. */
        public Builder<F> optionalLongInteger(String name, Function<F, Long> value) {
            return field(name, "integer", value::apply).optional();
        }

        public Builder<F> flag(String name, Predicate<F> value) {
            return field(name, "boolean", value::test);
        }

        public Builder<F> text(String name, Function<F, String> value) {
            return field(name, "text", value::apply);
        }

        /** An array, made as JSON only when the record's JSON or this field is asked for; null leaves it out. */
        public Builder<F> array(String name, Function<F, JsonNode> value) {
            return field(name, "array", value::apply);
        }

        /** An array of numbers, written as doubles; null leaves it out. */
        public Builder<F> numbers(String name, Function<F, double[]> value) {
            return field(name, "array", value::apply);
        }

        /** An array of flags. */
        public Builder<F> flags(String name, Function<F, boolean[]> value) {
            return field(name, "array", value::apply);
        }

        /** An array of texts. */
        public Builder<F> texts(String name, Function<F, List<String>> value) {
            return field(name, "array", value::apply);
        }

        /** An object, made as JSON only when the record's JSON or this field is asked for; null leaves it out. */
        public Builder<F> object(String name, Function<F, JsonNode> value) {
            return field(name, "object", value::apply);
        }

        /**
         * Fields named at run time (one per zone, one per button): each entry of the map is a field of its own,
         * written in the map's order. {@code placeholder} says what names them ({@code "<zone>"}) and {@code type}
         * what their values are; the values are of the kinds the class comment lists.
         */
        public Builder<F> entries(String placeholder, String type, Function<F, Map<String, ?>> value) {
            field(placeholder, type, value::apply);
            entries.set(entries.size() - 1, true);
            return this;
        }

        public Builder<F> unit(String unit) {
            return last(f -> new RecordField(f.name(), f.type(), unit, f.frame(), f.doc(), f.optional()));
        }

        /** What the value is measured from or expressed in: {@code "robot frame: x forward, y left"}. */
        public Builder<F> frame(String frame) {
            return last(f -> new RecordField(f.name(), f.type(), f.unit(), frame, f.doc(), f.optional()));
        }

        public Builder<F> doc(String doc) {
            return last(f -> new RecordField(f.name(), f.type(), f.unit(), f.frame(), doc, f.optional()));
        }

        /** The field declared last may be left out of a record. */
        public Builder<F> optional() {
            return last(f -> new RecordField(f.name(), f.type(), f.unit(), f.frame(), f.doc(), true));
        }

        public RecordLayout<F> build() {
            if (fields.isEmpty()) {
                throw new IllegalStateException(form.getSimpleName() + " declares no fields");
            }
            return new RecordLayout<>(form, fields, values, entries);
        }

        private Builder<F> field(String name, String type, Function<F, Object> value) {
            fields.add(new RecordField(name, type, "", "", "", false));
            values.add(Objects.requireNonNull(value, "value"));
            entries.add(false);
            return this;
        }

        private Builder<F> last(Function<RecordField, RecordField> change) {
            if (fields.isEmpty()) {
                throw new IllegalStateException("declare a field first");
            }
            fields.set(fields.size() - 1, change.apply(fields.get(fields.size() - 1)));
            return this;
        }
    }
}
