package org.habla.sample;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.BooleanNode;
import com.fasterxml.jackson.databind.node.DoubleNode;
import com.fasterxml.jackson.databind.node.IntNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.LongNode;
import com.fasterxml.jackson.databind.node.TextNode;
import java.io.IOException;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A typed record's fields as JSON: each field as a tree node ({@link #node}, what {@link RecordLayout#json} is made
 * of), or the whole record written field by field to a generator as that tree would be written, without making it
 * (what a control socket sends for every sample of a typed record). A non-finite number, which JSON cannot carry,
 * is written as {@code null}, as the edges write it in a tree. Where the tree would differ from the fields written
 * in turn (a field holding JSON with a non-finite number in it, a name given twice), nothing is written and the
 * caller makes the tree.
 */
public final class RecordJson {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private RecordJson() {
    }

    /**
     * @param fields the layout's fields, in order
     * @param entries for each field, whether it stands for entries named at run time (a map)
     * @param fixed   the names of the fixed fields
     * @param values  each field's value in the record (null for none)
     * @return false, having written nothing, when only the tree can be written right
     */
    static boolean write(List<RecordField> fields, List<Boolean> entries, Set<String> fixed, Object[] values,
            JsonGenerator g) throws IOException {
        Set<Object> named = null;
        for (int i = 0; i < values.length; i++) {
            if (values[i] instanceof Map<?, ?> map && entries.get(i)) {
                named = named == null ? new HashSet<>(fixed) : named;
                for (Map.Entry<?, ?> e : map.entrySet()) {
                    if (!named.add(e.getKey()) || !finite(e.getValue())) {
                        return false; // a name given twice is written once, where it came first: the tree's to do
                    }
                }
            } else if (!finite(values[i])) {
                return false;
            }
        }
        g.writeStartObject();
        for (int i = 0; i < values.length; i++) {
            if (values[i] instanceof Map<?, ?> map && entries.get(i)) {
                for (Map.Entry<?, ?> e : map.entrySet()) {
                    g.writeFieldName((String) e.getKey());
                    writeValue(e.getValue(), g);
                }
            } else if (values[i] != null) {
                g.writeFieldName(fields.get(i).name());
                writeValue(values[i], g);
            }
        }
        g.writeEndObject();
        return true;
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

    /** False for JSON with a non-finite number in it; true for any other field value. */
    private static boolean finite(Object v) {
        return !(v instanceof JsonNode n) || allFinite(n);
    }

    /** Whether every number in {@code node} is finite, as JSON must have them; an edge writes it as it is then. */
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

    /** Writes {@code d}, or {@code null} when it is not finite. */
    public static void writeNumber(double d, JsonGenerator g) throws IOException {
        if (Double.isFinite(d)) {
            g.writeNumber(d);
        } else {
            g.writeNull();
        }
    }
}
