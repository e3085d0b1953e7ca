package org.habla.config;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.reflect.GenericArrayType;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.Collection;
import java.util.Map;
import java.util.Optional;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;
import org.habla.plugin.ParamRange;

/**
 * The JSON Schema of one params record: an object whose properties are the record's components, typed
 * from their Java types and documented from their {@link Param} annotations (meaning, unit, default, range; a
 * {@link Param#defaultNote()} joins the description, since it is no value of the property's type).
 */
final class ParamsSchema {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private ParamsSchema() {
    }

    /** The schema of {@code type}'s params object; nested records become nested objects. */
    static ObjectNode of(Class<? extends Record> type) {
        ObjectNode schema = NODES.objectNode();
        schema.put("type", "object");
        schema.put("additionalProperties", false);
        ObjectNode properties = schema.putObject("properties");
        ArrayNode required = NODES.arrayNode();
        for (RecordComponent c : type.getRecordComponents()) {
            String name = ParamsBinder.jsonName(c);
            ObjectNode property = typeOf(c.getGenericType());
            Param doc = c.getAnnotation(Param.class);
            if (doc != null) {
                String unit = doc.unit().isEmpty() ? "" : " [" + doc.unit() + "]";
                String note = doc.defaultNote().isEmpty() ? "" : "; when absent: " + doc.defaultNote();
                property.put("description", doc.value() + unit + note);
                if (!doc.unit().isEmpty()) {
                    property.put("x-unit", doc.unit());
                }
                ParamDefaults.json(type, c).ifPresent(d -> property.set("default", d));
                ParamRange.of(doc).ifPresent(r -> range(numbers(property), r));
            }
            if (doc == null ? c.getType().isPrimitive() : doc.defaultValue().isEmpty() && doc.defaultNote().isEmpty()) {
                required.add(name);
            }
            properties.set(name, property);
        }
        if (!required.isEmpty()) {
            schema.set("required", required);
        }
        return schema;
    }

    /** Where a range applies: the property itself, or its items or values when it holds numbers. */
    private static ObjectNode numbers(ObjectNode property) {
        if (property.has("items")) {
            return (ObjectNode) property.get("items");
        }
        return property.get("additionalProperties") instanceof ObjectNode values ? values : property;
    }

    private static void range(ObjectNode s, ParamRange r) {
        if (r.greaterThan() != Double.NEGATIVE_INFINITY) {
            bound(s, "exclusiveMinimum", r.greaterThan());
        }
        if (r.min() != Double.NEGATIVE_INFINITY) {
            bound(s, "minimum", r.min());
        }
        if (r.max() != Double.POSITIVE_INFINITY) {
            bound(s, "maximum", r.max());
        }
    }

    private static void bound(ObjectNode s, String key, double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            s.put(key, (long) v);
        } else {
            s.put(key, v);
        }
    }

    /** The schema of a value of Java type {@code t}. */
    static ObjectNode typeOf(Type t) {
        ObjectNode s = NODES.objectNode();
        if (t instanceof ParameterizedType p && p.getRawType() instanceof Class<?> raw) {
            Type[] args = p.getActualTypeArguments();
            if (Collection.class.isAssignableFrom(raw)) {
                s.put("type", "array");
                s.set("items", typeOf(args[0]));
            } else if (Map.class.isAssignableFrom(raw)) {
                s.put("type", "object");
                s.set("additionalProperties", typeOf(args[1]));
            } else if (raw == Optional.class) {
                return typeOf(args[0]);
            } else {
                return typeOf(raw);
            }
            return s;
        }
        if (t instanceof GenericArrayType g) {
            s.put("type", "array");
            s.set("items", typeOf(g.getGenericComponentType()));
            return s;
        }
        if (!(t instanceof Class<?> c)) {
            return s;
        }
        if (c == int.class || c == long.class || c == short.class || c == byte.class || c == Integer.class
                || c == Long.class || c == Short.class || c == Byte.class || c == BigInteger.class) {
            s.put("type", "integer");
        } else if (c == double.class || c == float.class || c == Double.class || c == Float.class
                || c == BigDecimal.class) {
            s.put("type", "number");
        } else if (c == boolean.class || c == Boolean.class) {
            s.put("type", "boolean");
        } else if (c == String.class || c == char.class || c == Character.class) {
            s.put("type", "string");
        } else if (c.isEnum()) {
            s.put("type", "string");
            ArrayNode values = s.putArray("enum");
            for (Object v : c.getEnumConstants()) {
                values.add(((Enum<?>) v).name());
            }
        } else if (c.isArray()) {
            s.put("type", "array");
            s.set("items", typeOf(c.getComponentType()));
        } else if (c.isRecord()) {
            return of(c.asSubclass(Record.class));
        } else if (Collection.class.isAssignableFrom(c)) {
            s.put("type", "array");
        } else if (Map.class.isAssignableFrom(c) || ObjectNode.class.isAssignableFrom(c)) {
            s.put("type", "object");
        }
        return s;
    }
}
