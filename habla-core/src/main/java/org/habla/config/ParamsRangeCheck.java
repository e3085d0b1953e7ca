package org.habla.config;

import com.fasterxml.jackson.databind.JsonNode;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.util.Collection;
import java.util.Map;
import java.util.Optional;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;
import org.habla.plugin.ParamRange;

/**
 * Checks the ranges params records declare ({@link Param#min()}, {@link Param#max()}, {@link Param#greaterThan()})
 * on a params object whose defaults are filled in, before the record is built: every value outside its range is an
 * error at its JSON path, all of them together. A range applies to a number, or to each number of a list or map;
 * a value of another type is left for the binder to report, and records inside are checked the same way.
 */
final class ParamsRangeCheck {

    private ParamsRangeCheck() {
    }

    static void check(JsonNode node, Type type, JsonPath path, ConfigErrors errors) {
        if (node == null) {
            return;
        }
        if (type instanceof Class<?> c && c.isRecord() && node.isObject()) {
            for (RecordComponent component : c.getRecordComponents()) {
                String key = ParamDefaults.key(component);
                JsonNode value = node.get(key);
                if (value == null) {
                    continue;
                }
                Optional<ParamRange> range = ParamRange.of(component.getAnnotation(Param.class));
                range.ifPresent(r -> numbers(value, r, path.field(key), errors));
                check(value, component.getGenericType(), path.field(key), errors);
            }
        } else if (type instanceof ParameterizedType p && p.getRawType() instanceof Class<?> raw) {
            Type[] args = p.getActualTypeArguments();
            if (Collection.class.isAssignableFrom(raw) && node.isArray()) {
                for (int i = 0; i < node.size(); i++) {
                    check(node.get(i), args[0], path.index(i), errors);
                }
            } else if (Map.class.isAssignableFrom(raw) && node.isObject()) {
                node.fields().forEachRemaining(e -> check(e.getValue(), args[1], path.field(e.getKey()), errors));
            } else if (raw == Optional.class) {
                check(node, args[0], path, errors);
            }
        } else if (type instanceof Class<?> c && c.isArray() && node.isArray()) {
            for (int i = 0; i < node.size(); i++) {
                check(node.get(i), c.getComponentType(), path.index(i), errors);
            }
        }
    }

    /** The value, or each number of a list or map, against the range. */
    private static void numbers(JsonNode value, ParamRange range, JsonPath path, ConfigErrors errors) {
        if (value.isNumber()) {
            String refusal = range.refusal(value.doubleValue(), value.asText());
            if (refusal != null) {
                errors.add(path, refusal);
            }
        } else if (value.isArray()) {
            for (int i = 0; i < value.size(); i++) {
                numbers(value.get(i), range, path.index(i), errors);
            }
        } else if (value.isObject()) {
            value.fields().forEachRemaining(e -> numbers(e.getValue(), range, path.field(e.getKey()), errors));
        }
    }
}
