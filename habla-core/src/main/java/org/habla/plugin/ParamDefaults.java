package org.habla.plugin;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.lang.reflect.RecordComponent;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The defaults a params record declares in its {@link Param#defaultValue()} annotations, read once per
 * record type. The config loader fills a left-out key from here before the record is built; a record
 * built from Java code with a null takes the same value through {@link #or}, so each default is
 * written once, in the annotation.
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
     * The default of one component as JSON, or empty when it has none (required, or left to the record
     * as its {@link Param#defaultNote()} says).
     *
     * @throws IllegalStateException when the annotation's default is not JSON text
     */
    public static Optional<JsonNode> json(Class<?> type, RecordComponent component) {
        Param doc = component.getAnnotation(Param.class);
        if (doc == null || doc.defaultValue().isEmpty()) {
            return Optional.empty();
        }
        try {
            return Optional.of(JSON.readTree(doc.defaultValue()));
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(type.getName() + "." + component.getName() + ": defaultValue "
                    + doc.defaultValue() + " is not JSON text; words belong in defaultNote", e);
        }
    }

    /**
     * {@code value}, or when it is null the declared default of {@code type}'s component {@code name}, as
     * that component's Java type. For compact constructors called from Java with nulls.
     *
     * @throws IllegalArgumentException when {@code value} is null and the component declares no default
     */
    @SuppressWarnings("unchecked")
    public static <T> T or(Class<? extends Record> type, String name, T value) {
        if (value != null) {
            return value;
        }
        JsonNode d = DEFAULTS.get(type).get(name);
        if (d == null) {
            throw new IllegalArgumentException(name + " is required");
        }
        RecordComponent component = component(type, name);
        return (T) JSON.convertValue(d.deepCopy(), JSON.constructType(component.getGenericType()));
    }

    private static RecordComponent component(Class<? extends Record> type, String name) {
        for (RecordComponent c : type.getRecordComponents()) {
            if (c.getName().equals(name)) {
                return c;
            }
        }
        throw new IllegalArgumentException(type.getName() + " has no parameter " + name);
    }
}
