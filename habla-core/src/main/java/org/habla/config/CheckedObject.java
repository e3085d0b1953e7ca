package org.habla.config;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;

/**
 * One JSON object of a config, read key by key with every wrong key, type or range reported at its
 * path. A value that cannot be read yields its default (or empty) after the error is recorded, so
 * reading goes on and the next fault is found too.
 */
final class CheckedObject {

    private final ObjectNode node;
    private final JsonPath path;
    private final ConfigErrors errors;

    private CheckedObject(ObjectNode node, JsonPath path, ConfigErrors errors) {
        this.node = node;
        this.path = path;
        this.errors = errors;
    }

    /** The node as an object, or empty after an error if it is something else. */
    static Optional<CheckedObject> of(JsonNode node, JsonPath path, ConfigErrors errors) {
        if (node instanceof ObjectNode object) {
            return Optional.of(new CheckedObject(object, path, errors));
        }
        errors.add(path, "must be an object, not " + describe(node));
        return Optional.empty();
    }

    JsonPath path() {
        return path;
    }

    ObjectNode node() {
        return node;
    }

    boolean has(String key) {
        return node.has(key);
    }

    /** Reports every key not in {@code allowed}. */
    void allowOnly(Set<String> allowed) {
        String list = String.join(", ", new TreeSet<>(allowed));
        node.fieldNames().forEachRemaining(key -> {
            if (!allowed.contains(key)) {
                errors.add(path.field(key), "unknown key '" + key + "' (allowed: " + list + ")");
            }
        });
    }

    /** A required string; empty (after an error) when missing, not a string, or blank. */
    Optional<String> requiredString(String key) {
        if (!node.has(key)) {
            errors.add(path.field(key), "required key '" + key + "' is missing");
            return Optional.empty();
        }
        return optionalString(key);
    }

    /** An optional string; empty when absent, or after an error when not a non-blank string. */
    Optional<String> optionalString(String key) {
        JsonNode v = node.get(key);
        if (v == null) {
            return Optional.empty();
        }
        if (!v.isTextual()) {
            errors.add(path.field(key), "must be a string, not " + describe(v));
            return Optional.empty();
        }
        if (v.textValue().isBlank()) {
            errors.add(path.field(key), "must not be empty");
            return Optional.empty();
        }
        return Optional.of(v.textValue());
    }

    /** An optional integer within {@code min..max}; {@code dflt} when absent or wrong (after an error). */
    long integer(String key, long dflt, long min, long max) {
        JsonNode v = node.get(key);
        if (v == null) {
            return dflt;
        }
        if (!v.isIntegralNumber() || !v.canConvertToLong()) {
            errors.add(path.field(key), "must be an integer in " + min + ".." + max + ", not " + describe(v));
            return dflt;
        }
        long value = v.longValue();
        if (value < min || value > max) {
            errors.add(path.field(key), "must be in " + min + ".." + max + ", was " + value);
            return dflt;
        }
        return value;
    }

    /** An optional boolean; {@code dflt} when absent or wrong (after an error). */
    boolean bool(String key, boolean dflt) {
        JsonNode v = node.get(key);
        if (v == null) {
            return dflt;
        }
        if (!v.isBoolean()) {
            errors.add(path.field(key), "must be true or false, not " + describe(v));
            return dflt;
        }
        return v.booleanValue();
    }

    /** An optional nested object; empty when absent, or after an error when not an object. */
    Optional<CheckedObject> object(String key) {
        JsonNode v = node.get(key);
        return v == null ? Optional.empty() : of(v, path.field(key), errors);
    }

    /** The elements of an optional array (empty when absent, or after an error when not an array). */
    List<JsonNode> array(String key) {
        JsonNode v = node.get(key);
        if (v == null) {
            return List.of();
        }
        if (!v.isArray()) {
            errors.add(path.field(key), "must be an array, not " + describe(v));
            return List.of();
        }
        List<JsonNode> items = new ArrayList<>();
        v.elements().forEachRemaining(items::add);
        return items;
    }

    /** An optional object of strings, in file order; entries that are not strings are reported and left out. */
    Map<String, String> strings(String key) {
        Map<String, String> out = new LinkedHashMap<>();
        object(key).ifPresent(o -> o.node.properties().forEach(e -> {
            if (e.getValue().isTextual()) {
                out.put(e.getKey(), e.getValue().textValue());
            } else {
                errors.add(o.path.field(e.getKey()), "must be a string, not " + describe(e.getValue()));
            }
        }));
        return out;
    }

    /** How a JSON value is named in messages: "a string", "a number (5.5)", "an object". */
    static String describe(JsonNode v) {
        if (v == null || v.isMissingNode()) {
            return "nothing";
        }
        return switch (v.getNodeType()) {
            case STRING -> "a string (\"" + abbreviate(v.textValue()) + "\")";
            case NUMBER -> "a number (" + v.asText() + ")";
            case BOOLEAN -> "a boolean (" + v.asText() + ")";
            case NULL -> "null";
            case ARRAY -> "an array";
            case OBJECT, POJO -> "an object";
            default -> v.getNodeType().name().toLowerCase(java.util.Locale.ROOT);
        };
    }

    private static String abbreviate(String s) {
        return s.length() <= 40 ? s : s.substring(0, 37) + "...";
    }
}
