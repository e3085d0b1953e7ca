package org.habla.sample;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.MissingNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Function;

/**
 * A small structured value (a pose, a distance and angle, a blob list): a JSON object, or a typed
 * {@link RecordForm}. A typed record answers its accessors from the form's {@link RecordLayout} without making
 * JSON; its JSON is made the first time an edge asks for it ({@link #jsonView()}, {@link #json()}). Immutable:
 * JSON is copied in and copied out, and a form is immutable itself.
 *
 * <p>Two records are equal when their JSON is: two typed records of one form compare their forms, a typed
 * record and a JSON one compare JSON (the typed one's is made then, which happens at an edge or in a test).
 */
public final class RecordValue implements Payload {

    private final RecordForm form;
    private volatile ObjectNode fields;

    private RecordValue(ObjectNode fields, RecordForm form) {
        this.fields = fields;
        this.form = form;
    }

    public static RecordValue of(ObjectNode fields) {
        return new RecordValue(Objects.requireNonNull(fields, "fields").deepCopy(), null);
    }

    /** A record that carries {@code form} itself: the methods of this daemon read it without JSON. */
    public static RecordValue of(RecordForm form) {
        return new RecordValue(null, Objects.requireNonNull(form, "form"));
    }

    /** Starts a record: {@code RecordValue.builder().put("distanceM", 1.2).build()}. */
    public static Builder builder() {
        return new Builder();
    }

    /** The typed value this record carries, if it was made from one of type {@code type}. */
    public <T extends RecordForm> Optional<T> form(Class<T> type) {
        return type.isInstance(form) ? Optional.of(type.cast(form)) : Optional.empty();
    }

    /**
     * The typed value: the one this record carries when it is a {@code type}, else {@code read} applied to this
     * record (a record that came as JSON: from a socket, a recording or a worker).
     */
    public <T extends RecordForm> T as(Class<T> type, Function<RecordValue, T> read) {
        return type.isInstance(form) ? type.cast(form) : read.apply(this);
    }

    /** The typed value this record carries, or null when it is plain JSON. */
    public RecordForm carriesForm() {
        return form;
    }

    /** A copy of the fields. */
    public ObjectNode json() {
        return fields().deepCopy();
    }

    /**
     * The fields themselves, made once and shared: only for writing them out (encoders, recorders), never to be
     * modified.
     */
    public ObjectNode jsonView() {
        return fields();
    }

    /** Whether this record's JSON exists: it came as JSON, or an edge has asked for it. */
    public boolean hasJson() {
        return fields != null;
    }

    private ObjectNode fields() {
        ObjectNode f = fields;
        if (f == null) {
            f = form.toJson();
            fields = f; // two threads may both make it: the same content, either one is kept
        }
        return f;
    }

    /** The field's node (read only: do not modify), or a missing node. A typed record makes only this node. */
    public JsonNode get(String name) {
        if (form != null) {
            Object v = form.layout().value(form, name);
            return v == null ? MissingNode.getInstance() : RecordJson.node(v);
        }
        return fields.path(name);
    }

    public double number(String name) {
        if (form != null) {
            if (form.layout().value(form, name) instanceof Number n) {
                return n.doubleValue();
            }
            throw new IllegalArgumentException("record has no number field '" + name + "'");
        }
        JsonNode n = fields.get(name);
        if (n == null || !n.isNumber()) {
            throw new IllegalArgumentException("record has no number field '" + name + "'");
        }
        return n.doubleValue();
    }

    public String text(String name) {
        if (form != null) {
            if (form.layout().value(form, name) instanceof String t) {
                return t;
            }
            throw new IllegalArgumentException("record has no text field '" + name + "'");
        }
        JsonNode n = fields.get(name);
        if (n == null || !n.isTextual()) {
            throw new IllegalArgumentException("record has no text field '" + name + "'");
        }
        return n.textValue();
    }

    public boolean has(String name) {
        return form != null ? form.layout().value(form, name) != null : fields.has(name);
    }

    @Override
    public PayloadKind kind() {
        return PayloadKind.RECORD;
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof RecordValue r)) {
            return false;
        }
        if (form != null && r.form != null && form.getClass() == r.form.getClass()) {
            return form.equals(r.form);
        }
        return fields().equals(r.fields());
    }

    @Override
    public int hashCode() {
        return form != null ? form.layout().hash(form) : RecordHash.ofJson(fields);
    }

    @Override
    public String toString() {
        return "RecordValue" + fields();
    }

    /** Builds a record field by field; the builder may go on after {@link #build()} without changing what it built. */
    public static final class Builder {
        private ObjectNode node = JsonNodeFactory.instance.objectNode();
        private boolean handedOff;

        private ObjectNode node() {
            if (handedOff) {
                node = node.deepCopy();
                handedOff = false;
            }
            return node;
        }

        public Builder put(String name, double value) {
            node().put(name, value);
            return this;
        }

        public Builder put(String name, long value) {
            node().put(name, value);
            return this;
        }

        public Builder put(String name, boolean value) {
            node().put(name, value);
            return this;
        }

        public Builder put(String name, String value) {
            node().put(name, value);
            return this;
        }

        public Builder set(String name, JsonNode value) {
            node().set(name, value.deepCopy());
            return this;
        }

        public RecordValue build() {
            handedOff = true;
            return new RecordValue(node, null);
        }
    }
}
