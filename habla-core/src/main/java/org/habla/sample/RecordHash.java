package org.habla.sample;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Iterator;
import java.util.Map;

/**
 * The hash of a record that its JSON and its typed form give alike, so a typed record and the same record read from
 * JSON hash equal: the sum over its fields of the name's hash and the value's, numbers by their double value, texts
 * and flags by theirs, arrays and objects counting for nothing.
 */
final class RecordHash {

    private RecordHash() {
    }

    /** One field's share: its name and its value, a JSON node or a value of a {@link RecordLayout} field. */
    static int of(String name, Object value) {
        return name.hashCode() ^ scalar(value);
    }

    /** The hash of a record whose JSON is {@code fields}. */
    static int ofJson(ObjectNode fields) {
        int h = 0;
        for (Iterator<Map.Entry<String, JsonNode>> it = fields.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            h += of(e.getKey(), e.getValue());
        }
        return h;
    }

    private static int scalar(Object v) {
        if (v instanceof JsonNode n) {
            return n.isNumber() ? Double.hashCode(n.doubleValue()) : n.isTextual() ? n.textValue().hashCode()
                    : n.isBoolean() ? Boolean.hashCode(n.booleanValue()) : 0;
        }
        return v instanceof Number n ? Double.hashCode(n.doubleValue())
                : v instanceof String || v instanceof Boolean ? v.hashCode() : 0;
    }
}
