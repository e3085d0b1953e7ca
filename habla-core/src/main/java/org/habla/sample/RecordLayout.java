package org.habla.sample;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.BooleanNode;
import com.fasterxml.jackson.databind.node.DoubleNode;
import com.fasterxml.jackson.databind.node.IntNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.LongNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.databind.node.TextNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
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
        this.index = Map.copyOf(byName);
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
        List<String> names = new ArrayList<>();
        for (int i = 0; i < fields.size(); i++) {
            if (!entries.get(i)) {
                names.add(fields.get(i).name());
            }
        }
        return names;
    }

    /** The record as JSON, field by field in declared order, leaving out the fields whose value is null. */
    public ObjectNode json(RecordForm value) {
        F f = form.cast(value);
        ObjectNode o = NODES.objectNode();
        for (int i = 0; i < fields.size(); i++) {
            Object v = values.get(i).apply(f);
            if (v instanceof Map<?, ?> each && entries.get(i)) {
                each.forEach((name, x) -> o.set((String) name, node(x)));
            } else if (v != null) {
                o.set(fields.get(i).name(), node(v));
            }
        }
        return o;
    }

    /**
     * Writes the record's JSON object straight to {@code g}, byte for byte what {@link #json} would be written as,
     * without making it: a non-finite number (which JSON cannot carry) as {@code null}. Returns false, having
     * written nothing, when a field holds JSON with a non-finite number in it, which only {@link #json} copes with.
     */
    public boolean write(RecordForm value, JsonGenerator g) throws IOException {
        F f = form.cast(value);
        Object[] each = new Object[fields.size()];
        java.util.Set<Object> named = null;
        for (int i = 0; i < each.length; i++) {
            each[i] = values.get(i).apply(f);
            if (each[i] instanceof Map<?, ?> map && entries.get(i)) {
                named = named == null ? new java.util.HashSet<>(index.keySet()) : named;
                for (Map.Entry<?, ?> e : map.entrySet()) {
                    if (!named.add(e.getKey()) || !finite(e.getValue())) {
                        return false; // a name given twice is written once, where it came first: json's to do
                    }
                }
            } else if (!finite(each[i])) {
                return false;
            }
        }
        g.writeStartObject();
        for (int i = 0; i < each.length; i++) {
            if (each[i] instanceof Map<?, ?> map && entries.get(i)) {
                for (Map.Entry<?, ?> e : map.entrySet()) {
                    g.writeFieldName((String) e.getKey());
                    writeValue(e.getValue(), g);
                }
            } else if (each[i] != null) {
                g.writeFieldName(fields.get(i).name());
                writeValue(each[i], g);
            }
        }
        g.writeEndObject();
        return true;
    }

    /** False for JSON with a non-finite number in it; true for any other field value. */
    private static boolean finite(Object v) {
        return !(v instanceof JsonNode n) || allFinite(n);
    }

    /** Whether every number in {@code node} is finite, as JSON must have them. */
    public static boolean allFinite(JsonNode node) {
        if (node.isFloatingPointNumber()) {
            return Double.isFinite(node.doubleValue());
        }
        if (node.isContainerNode()) {
            for (JsonNode child : node) {
                if (!allFinite(child)) {
                    return false;
                }
            }
        }
        return true;
    }

    private static void writeValue(Object v, JsonGenerator g) throws IOException {
        switch (v) {
            case Double d -> writeNumber(d, g);
            case Integer i -> g.writeNumber(i);
            case Long l -> g.writeNumber(l);
            case Boolean b -> g.writeBoolean(b);
            case String s -> g.writeString(s);
            case JsonNode n -> g.writeTree(n);
            case double[] numbers -> {
                g.writeStartArray();
                for (double d : numbers) {
                    writeNumber(d, g);
                }
                g.writeEndArray();
            }
            case boolean[] flags -> {
                g.writeStartArray();
                for (boolean b : flags) {
                    g.writeBoolean(b);
                }
                g.writeEndArray();
            }
            case List<?> texts -> {
                g.writeStartArray();
                for (Object t : texts) {
                    g.writeString((String) t);
                }
                g.writeEndArray();
            }
            default -> throw new IllegalStateException("a record field cannot hold a " + v.getClass().getName());
        }
    }

    private static void writeNumber(double d, JsonGenerator g) throws IOException {
        if (Double.isFinite(d)) {
            g.writeNumber(d);
        } else {
            g.writeNull();
        }
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

    /** A field's value as a JSON node; an array of numbers, flags or texts as a JSON array. */
    static JsonNode node(Object v) {
        return switch (v) {
            case Double d -> DoubleNode.valueOf(d);
            case Integer i -> IntNode.valueOf(i);
            case Long l -> LongNode.valueOf(l);
            case Boolean b -> BooleanNode.valueOf(b);
            case String s -> TextNode.valueOf(s);
            case JsonNode n -> n;
            case double[] numbers -> {
                ArrayNode a = NODES.arrayNode(numbers.length);
                Arrays.stream(numbers).forEach(a::add);
                yield a;
            }
            case boolean[] flags -> {
                ArrayNode a = NODES.arrayNode(flags.length);
                for (boolean f : flags) {
                    a.add(f);
                }
                yield a;
            }
            case List<?> texts -> {
                ArrayNode a = NODES.arrayNode(texts.size());
                texts.forEach(t -> a.add((String) t));
                yield a;
            }
            default -> throw new IllegalStateException("a record field cannot hold a " + v.getClass().getName());
        };
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
