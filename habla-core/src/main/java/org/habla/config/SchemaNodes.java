package org.habla.config;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** The small JSON Schema nodes {@link ConfigSchema} is built of: typed properties, references, conditions. */
final class SchemaNodes {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private SchemaNodes() {
    }

    static ObjectNode bool(boolean dflt, String description) {
        return NODES.objectNode().put("type", "boolean").put("default", dflt).put("description", description);
    }

    static ObjectNode when(String key, String value, ObjectNode thenProperties) {
        ObjectNode c = NODES.objectNode();
        ObjectNode condition = withRequired(c.putObject("if"), key);
        condition.set("properties", props(key, NODES.objectNode().put("const", value)));
        c.putObject("then").set("properties", thenProperties);
        return c;
    }

    static ObjectNode withRequired(ObjectNode schema, String... keys) {
        schema.set("required", strings(keys));
        return schema;
    }

    static ObjectNode object(String description) {
        return NODES.objectNode().put("description", description).put("type", "object")
                .put("additionalProperties", false);
    }

    static ObjectNode string(String description) {
        return NODES.objectNode().put("description", description).put("type", "string");
    }

    static ObjectNode integer(long min, long max, long dflt, String description) {
        return integer(min, max, description).put("default", dflt);
    }

    static ObjectNode integer(long min, long max, String description) {
        return NODES.objectNode().put("description", description).put("type", "integer")
                .put("minimum", min).put("maximum", max);
    }

    static ObjectNode ref(String def) {
        return NODES.objectNode().put("$ref", "#/$defs/" + def);
    }

    static ObjectNode props(Object... keysAndSchemas) {
        ObjectNode p = NODES.objectNode();
        for (int i = 0; i < keysAndSchemas.length; i += 2) {
            p.set((String) keysAndSchemas[i], (JsonNode) keysAndSchemas[i + 1]);
        }
        return p;
    }

    static ArrayNode strings(String... values) {
        return strings(List.of(values));
    }

    static ArrayNode strings(java.util.Collection<String> values) {
        ArrayNode a = NODES.arrayNode();
        values.forEach(a::add);
        return a;
    }

    /** Sorts the keys of every {@code properties} and {@code $defs} object, recursively. */
    static void sortKeys(JsonNode node) {
        if (node instanceof ObjectNode o) {
            for (String key : List.of("properties", "$defs")) {
                if (o.get(key) instanceof ObjectNode inner) {
                    List<Map.Entry<String, JsonNode>> entries = new ArrayList<>(inner.properties());
                    entries.sort(Map.Entry.comparingByKey());
                    inner.removeAll();
                    entries.forEach(e -> inner.set(e.getKey(), e.getValue()));
                }
            }
            o.elements().forEachRemaining(SchemaNodes::sortKeys);
        } else if (node instanceof ArrayNode a) {
            a.elements().forEachRemaining(SchemaNodes::sortKeys);
        }
    }
}
