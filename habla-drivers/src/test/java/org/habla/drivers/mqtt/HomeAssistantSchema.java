package org.habla.drivers.mqtt;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * Checks a Home Assistant MQTT discovery payload against what Home Assistant documents for its component, as the
 * test fixture {@code home-assistant/mqtt-discovery-schema.json} writes it down: every key known and of its type,
 * the required ones there, no deprecated key, and the documented rules between keys.
 */
final class HomeAssistantSchema {

    private static final Pattern ENTITY_ID = Pattern.compile("([a-z_]+)\\.[a-z0-9_]+");
    private final JsonNode schema;

    private HomeAssistantSchema(JsonNode schema) {
        this.schema = schema;
    }

    /** The schema of the test fixture. */
    static HomeAssistantSchema load() {
        try (InputStream in = HomeAssistantSchema.class.getResourceAsStream("/home-assistant/mqtt-discovery-schema.json")) {
            return new HomeAssistantSchema(new ObjectMapper().readTree(in));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** What is wrong with {@code payload} as the discovery config of a {@code component}; empty when nothing. */
    List<String> violations(String component, JsonNode payload) {
        List<String> errors = new ArrayList<>();
        JsonNode comp = schema.path("components").path(component);
        if (comp.isMissingNode()) {
            errors.add("no component '" + component + "' in the schema");
            return errors;
        }
        if (!payload.isObject()) {
            errors.add("the payload is not a JSON object");
            return errors;
        }
        for (JsonNode req : comp.path("required")) {
            if (!payload.has(req.asText())) {
                errors.add(component + ": '" + req.asText() + "' is required");
            }
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = payload.fields(); it.hasNext();) {
            Map.Entry<String, JsonNode> e = it.next();
            JsonNode spec = comp.path("keys").has(e.getKey()) ? comp.path("keys").path(e.getKey())
                    : schema.path("common").path(e.getKey());
            if (spec.isMissingNode()) {
                errors.add(component + ": unknown key '" + e.getKey() + "'");
            } else if (spec.has("deprecated")) {
                errors.add(component + ": '" + e.getKey() + "' is deprecated: " + spec.path("deprecated").asText());
            } else {
                value(component + "." + e.getKey(), spec, e.getValue(), errors);
            }
        }
        rules(component, payload, errors);
        return errors;
    }

    private void value(String path, JsonNode spec, JsonNode v, List<String> errors) {
        if (v.isNull()) {
            if (!spec.path("nullable").asBoolean()) {
                errors.add(path + " may not be null");
            }
            return;
        }
        List<String> types = new ArrayList<>();
        if (spec.path("type").isArray()) {
            spec.path("type").forEach(t -> types.add(t.asText()));
        } else {
            types.add(spec.path("type").asText());
        }
        if (types.stream().noneMatch(t -> is(t, v))) {
            errors.add(path + " must be " + String.join(" or ", types) + ", was " + v);
            return;
        }
        if (spec.has("oneOf") && !contains(spec.path("oneOf"), v)) {
            errors.add(path + " must be one of " + spec.path("oneOf") + ", was " + v);
        }
        if (spec.has("min") && v.isNumber() && v.asLong() < spec.path("min").asLong()
                || spec.has("max") && v.isNumber() && v.asLong() > spec.path("max").asLong()) {
            errors.add(path + " is out of range: " + v);
        }
        if (spec.has("map")) {
            map(path, schema.path("maps").path(spec.path("map").asText()), v, errors);
        }
        if (spec.has("items")) {
            for (int i = 0; i < v.size(); i++) {
                map(path + "[" + i + "]", schema.path("maps").path(spec.path("items").asText()), v.get(i), errors);
            }
        }
    }

    private void map(String path, JsonNode spec, JsonNode v, List<String> errors) {
        if (!v.isObject()) {
            errors.add(path + " must be a map");
            return;
        }
        for (JsonNode req : spec.path("required")) {
            if (!v.has(req.asText())) {
                errors.add(path + ": '" + req.asText() + "' is required");
            }
        }
        if (spec.has("oneOfRequired")) {
            boolean any = false;
            for (JsonNode k : spec.path("oneOfRequired")) {
                any |= v.has(k.asText());
            }
            if (!any) {
                errors.add(path + ": one of " + spec.path("oneOfRequired") + " is required");
            }
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = v.fields(); it.hasNext();) {
            Map.Entry<String, JsonNode> e = it.next();
            JsonNode keySpec = spec.path("keys").path(e.getKey());
            if (keySpec.isMissingNode()) {
                errors.add(path + ": unknown key '" + e.getKey() + "'");
            } else {
                value(path + "." + e.getKey(), keySpec, e.getValue(), errors);
            }
        }
    }

    private void rules(String component, JsonNode p, List<String> errors) {
        if (p.has("availability") && p.has("availability_topic")) {
            errors.add(component + ": availability and availability_topic exclude each other");
        }
        if (p.has("platform")) {
            errors.add(component + ": platform belongs only in a device-based discovery payload");
        }
        if (p.has("default_entity_id")) {
            var m = ENTITY_ID.matcher(p.path("default_entity_id").asText());
            if (!m.matches() || !m.group(1).equals(component)) {
                errors.add(component + ": default_entity_id must be '" + component + ".<lower-case id>', was "
                        + p.path("default_entity_id"));
            }
        }
        if (!component.equals("sensor")) {
            return;
        }
        String deviceClass = p.path("device_class").asText("");
        if (p.has("options") && (!deviceClass.equals("enum") || p.has("state_class")
                || p.has("unit_of_measurement"))) {
            errors.add("sensor: options needs device_class enum and neither state_class nor unit_of_measurement");
        }
        if (!deviceClass.isEmpty() && p.has("state_class")
                && contains(schema.path("sensorDeviceClassesWithoutStateClass"), p.path("device_class"))) {
            errors.add("sensor: a " + deviceClass + " sensor has no state_class");
        }
        JsonNode units = schema.path("sensorDeviceClassUnits").path(deviceClass);
        if (!deviceClass.isEmpty() && !deviceClass.equals("enum") && units.isMissingNode()) {
            errors.add("sensor: device_class '" + deviceClass + "' is not in the fixture's table");
        } else if (!deviceClass.isEmpty() && !p.path("unit_of_measurement").isMissingNode()
                && !p.path("unit_of_measurement").isNull() && !contains(units, p.path("unit_of_measurement"))) {
            errors.add("sensor: unit " + p.path("unit_of_measurement") + " does not go with device_class "
                    + deviceClass + " (" + units + ")");
        }
    }

    private static boolean is(String type, JsonNode v) {
        return switch (type) {
            case "string" -> v.isTextual();
            case "integer" -> v.isIntegralNumber();
            case "boolean" -> v.isBoolean();
            case "list" -> v.isArray();
            case "map" -> v.isObject();
            default -> false;
        };
    }

    private static boolean contains(JsonNode array, JsonNode v) {
        for (JsonNode a : array) {
            if (a.equals(v)) {
                return true;
            }
        }
        return false;
    }
}
