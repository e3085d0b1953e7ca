package org.habla.sample;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Objects;

/**
 * A small structured value: a JSON object (a pose, a distance and angle, a blob list).
 * The object is copied in and copied out, so the record stays immutable.
 */
public final class RecordValue implements Payload {

    private final ObjectNode fields;

    private RecordValue(ObjectNode fields) {
        this.fields = fields;
    }

    public static RecordValue of(ObjectNode fields) {
        return new RecordValue(Objects.requireNonNull(fields, "fields").deepCopy());
    }

    /** Starts a record: {@code RecordValue.builder().put("distanceM", 1.2).build()}. */
    public static Builder builder() {
        return new Builder();
    }

    /** A copy of the fields. */
    public ObjectNode json() {
        return fields.deepCopy();
    }

    /** The field's node (read only: do not modify), or a missing node. */
    public JsonNode get(String name) {
        return fields.path(name);
    }

    public double number(String name) {
        JsonNode n = fields.get(name);
        if (n == null || !n.isNumber()) {
            throw new IllegalArgumentException("record has no number field '" + name + "'");
        }
        return n.doubleValue();
    }

    public String text(String name) {
        JsonNode n = fields.get(name);
        if (n == null || !n.isTextual()) {
            throw new IllegalArgumentException("record has no text field '" + name + "'");
        }
        return n.textValue();
    }

    public boolean has(String name) {
        return fields.has(name);
    }

    @Override
    public PayloadKind kind() {
        return PayloadKind.RECORD;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof RecordValue r && fields.equals(r.fields);
    }

    @Override
    public int hashCode() {
        return fields.hashCode();
    }

    @Override
    public String toString() {
        return "RecordValue" + fields;
    }

    /** Builds a record field by field. */
    public static final class Builder {
        private final ObjectNode node = JsonNodeFactory.instance.objectNode();

        public Builder put(String name, double value) {
            node.put(name, value);
            return this;
        }

        public Builder put(String name, long value) {
            node.put(name, value);
            return this;
        }

        public Builder put(String name, boolean value) {
            node.put(name, value);
            return this;
        }

        public Builder put(String name, String value) {
            node.put(name, value);
            return this;
        }

        public Builder set(String name, JsonNode value) {
            node.set(name, value.deepCopy());
            return this;
        }

        public RecordValue build() {
            return new RecordValue(node.deepCopy());
        }
    }
}
