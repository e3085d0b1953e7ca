package org.habla.plugin;

import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.util.Collection;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The defaults a params record declares in its {@link Param#defaultValue()} annotations. The config
 * loader fills left-out keys with them ({@link #filled}) before the record is built, so a record receives its
 * defaults when it is bound and each default is written once, in the annotation; Java code that needs a record
 * binds one too ({@code org.habla.config.ParamsJson#defaults}). Records inside a params object (a list of channel
 * specs, a map of colour ranges) and inside a default are filled the same way.
 */
public final class ParamDefaults {

    private static final ObjectMapper JSON = new ObjectMapper();

    private static final ClassValue<Map<String, JsonNode>> DEFAULTS = new ClassValue<>() {
        @Override
        protected Map<String, JsonNode> computeValue(Class<?> type) {
            Map<String, JsonNode> defaults = new HashMap<>();
            for (RecordComponent c : type.getRecordComponents()) {
                json(type, c).ifPresent(d -> defaults.put(c.getName(), d));
            }
            return Map.copyOf(defaults);
        }
    };

    private ParamDefaults() {
    }

    /**
     * The default of one component as JSON, records inside it filled with their own defaults, or empty when it
     * has none (required, or left to the record as its {@link Param#defaultNote()} says).
     *
     * @throws IllegalStateException when the annotation's default is not JSON text
     */
    public static Optional<JsonNode> json(Class<?> type, RecordComponent component) {
        Param doc = component.getAnnotation(Param.class);
        if (doc == null || doc.defaultValue().isEmpty()) {
            return Optional.empty();
        }
        try {
            JsonNode d = JSON.readTree(doc.defaultValue());
            fill(d, component.getGenericType());
            return Optional.of(d);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(type.getName() + "." + component.getName() + ": defaultValue "
                    + doc.defaultValue() + " is not JSON text; words belong in defaultNote", e);
        }
    }

    /**
     * A copy of the params object {@code node} with every left-out (or null) key of {@code type} filled
     * with its declared default, records inside included. A value of the wrong shape is left as it is, for
     * the binder to report; {@code node} itself is not changed.
     */
    public static JsonNode filled(JsonNode node, Class<? extends Record> type) {
        JsonNode copy = node.deepCopy();
        fill(copy, type);
        return copy;
    }

    /** The JSON key of a record component: its {@link JsonProperty} name, else its own name. */
    public static String key(RecordComponent c) {
        JsonProperty p = c.getAnnotation(JsonProperty.class);
        if (p == null && c.getAccessor() != null) {
            p = c.getAccessor().getAnnotation(JsonProperty.class);
        }
        return p != null && !p.value().isEmpty() ? p.value() : c.getName();
    }

    private static void fill(JsonNode node, Type type) {
        if (type instanceof Class<?> c && c.isRecord() && node instanceof ObjectNode object) {
            for (RecordComponent component : c.getRecordComponents()) {
                JsonNode value = object.get(key(component));
                boolean absent = value == null || value.isNull();
                JsonNode d = absent ? DEFAULTS.get(c).get(component.getName()) : null;
                if (d != null) {
                    JsonNode copy = d.deepCopy();
                    object.set(key(component), copy);
                    fill(copy, component.getGenericType());
                } else if (value != null) {
                    fill(value, component.getGenericType());
                }
            }
        } else if (type instanceof ParameterizedType p && p.getRawType() instanceof Class<?> raw) {
            Type[] args = p.getActualTypeArguments();
            if (Collection.class.isAssignableFrom(raw) && node.isArray()) {
                node.forEach(element -> fill(element, args[0]));
            } else if (Map.class.isAssignableFrom(raw) && node.isObject()) {
                node.forEach(value -> fill(value, args[1]));
            } else if (raw == Optional.class) {
                fill(node, args[0]);
            }
        } else if (type instanceof Class<?> c && c.isArray() && node.isArray()) {
            node.forEach(element -> fill(element, c.getComponentType()));
        }
    }
}
