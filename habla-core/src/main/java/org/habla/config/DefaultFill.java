package org.habla.config;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.util.Collection;
import java.util.Iterator;
import java.util.Map;
import java.util.Optional;
import org.habla.plugin.ParamDefaults;

/**
 * Fills a params object's left-out (or null) keys with the defaults its record declares in
 * {@link org.habla.plugin.Param#defaultValue()}, before the record is built, so the record's
 * constructor sees every default already in place. Records inside the params (a list of channel
 * specs, a map of colour ranges) are filled the same way. A value of the wrong shape is left as it is,
 * for the binder to report.
 */
final class DefaultFill {

    private DefaultFill() {
    }

    /** A copy of {@code node} with every declared default filled in; {@code node} itself is not changed. */
    static JsonNode of(JsonNode node, Class<? extends Record> type) {
        JsonNode copy = node.deepCopy();
        fill(copy, type);
        return copy;
    }

    private static void fill(JsonNode node, Type type) {
        if (type instanceof Class<?> c && c.isRecord() && node instanceof ObjectNode object) {
            for (RecordComponent component : c.getRecordComponents()) {
                String key = ParamsBinder.jsonName(component);
                JsonNode value = object.get(key);
                boolean absent = value == null || value.isNull() && !component.getType().isPrimitive();
                Optional<JsonNode> d = absent ? ParamDefaults.json(c, component) : Optional.empty();
                if (d.isPresent()) {
                    object.set(key, d.get());
                } else if (value != null) {
                    fill(value, component.getGenericType());
                }
            }
        } else if (type instanceof ParameterizedType p && p.getRawType() instanceof Class<?> raw) {
            Type[] args = p.getActualTypeArguments();
            if (Collection.class.isAssignableFrom(raw) && node.isArray()) {
                node.forEach(element -> fill(element, args[0]));
            } else if (Map.class.isAssignableFrom(raw) && node.isObject()) {
                for (Iterator<JsonNode> values = node.elements(); values.hasNext(); ) {
                    fill(values.next(), args[1]);
                }
            } else if (raw == Optional.class) {
                fill(node, args[0]);
            }
        } else if (type instanceof Class<?> c && c.isArray() && node.isArray()) {
            node.forEach(element -> fill(element, c.getComponentType()));
        }
    }
}
