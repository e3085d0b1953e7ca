package org.habla.config;

import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonMappingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.MapperFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.cfg.CoercionAction;
import com.fasterxml.jackson.databind.cfg.CoercionInputShape;
import com.fasterxml.jackson.databind.exc.InvalidNullException;
import com.fasterxml.jackson.databind.exc.MismatchedInputException;
import com.fasterxml.jackson.databind.exc.UnrecognizedPropertyException;
import com.fasterxml.jackson.databind.exc.ValueInstantiationException;
import com.fasterxml.jackson.databind.json.JsonMapper;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.type.LogicalType;
import java.lang.reflect.RecordComponent;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Optional;
import java.util.TreeSet;
import java.util.regex.Pattern;
import org.habla.plugin.ParamDefaults;

/**
 * Binds a method's or an interface's {@code params} object to its type's params record, strictly: no
 * unknown keys, no nulls for primitives, no {@code "5"} for a number or {@code 5} for a string. Keys
 * left out are first filled with their declared defaults ({@link ParamDefaults#filled}), and numbers are checked
 * against the ranges their {@link org.habla.plugin.Param} annotations declare ({@link ParamsRangeCheck}). Every
 * failure becomes a {@link ConfigError} at the JSON path of the offending value; an exception thrown by
 * the record's constructor becomes an error at the parameter it names, or at {@code params}.
 */
final class ParamsBinder {

    /** The strict mapper params are bound with. */
    static final ObjectMapper STRICT = JsonMapper.builder()
            .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES,
                    DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES,
                    DeserializationFeature.FAIL_ON_NUMBERS_FOR_ENUMS,
                    DeserializationFeature.FAIL_ON_TRAILING_TOKENS,
                    DeserializationFeature.FAIL_ON_READING_DUP_TREE_KEY)
            .disable(DeserializationFeature.ACCEPT_FLOAT_AS_INT)
            .disable(MapperFeature.ALLOW_COERCION_OF_SCALARS)
            .withCoercionConfigDefaults(c -> c.setAcceptBlankAsEmpty(false)
                    .setCoercion(CoercionInputShape.EmptyString, CoercionAction.Fail))
            .withCoercionConfig(LogicalType.Textual, c -> c
                    .setCoercion(CoercionInputShape.Integer, CoercionAction.Fail)
                    .setCoercion(CoercionInputShape.Float, CoercionAction.Fail)
                    .setCoercion(CoercionInputShape.Boolean, CoercionAction.Fail))
            .withCoercionConfig(LogicalType.Integer, c -> c
                    .setCoercion(CoercionInputShape.String, CoercionAction.Fail)
                    .setCoercion(CoercionInputShape.Float, CoercionAction.Fail))
            .withCoercionConfig(LogicalType.Float, c -> c
                    .setCoercion(CoercionInputShape.String, CoercionAction.Fail))
            .withCoercionConfig(LogicalType.Boolean, c -> c
                    .setCoercion(CoercionInputShape.String, CoercionAction.Fail)
                    .setCoercion(CoercionInputShape.Integer, CoercionAction.Fail))
            .build();

    private ParamsBinder() {
    }

    /**
     * The bound record, or empty after recording every error found.
     *
     * @param params the {@code params} node, or null when the key is absent
     */
    static Optional<Record> bind(JsonNode params, Class<? extends Record> type, JsonPath path, ConfigErrors errors) {
        return bind(params, type, path, errors, java.nio.file.Path.of("").toAbsolutePath());
    }

    /**
     * As {@link #bind(JsonNode, Class, JsonPath, ConfigErrors)}, with relative paths of file params
     * ({@link org.habla.plugin.Param#file()}) taken from {@code baseDir}.
     */
    static Optional<Record> bind(JsonNode params, Class<? extends Record> type, JsonPath path, ConfigErrors errors,
            java.nio.file.Path baseDir) {
        JsonNode node = params == null ? JsonNodeFactory.instance.objectNode() : params;
        if (!node.isObject()) {
            errors.add(path, "must be an object, not " + CheckedObject.describe(node));
            return Optional.empty();
        }
        int before = errors.size();
        List<String> names = jsonNames(type);
        node.fieldNames().forEachRemaining(key -> {
            if (!names.contains(key)) {
                errors.add(path.field(key), "unknown parameter '" + key + "' (" + known(names) + ")");
            }
        });
        node = ParamDefaults.filled(node, type);
        for (RecordComponent c : type.getRecordComponents()) {
            if (c.getType().isPrimitive() && !node.has(jsonName(c))) {
                errors.add(path.field(jsonName(c)), "required parameter '" + jsonName(c) + "' is missing");
            }
        }
        if (errors.size() == before) {
            ParamsRangeCheck.check(node, type, path, errors);
        }
        if (errors.size() > before) {
            return Optional.empty();
        }
        node = withFilesResolved(node, type, baseDir);
        try {
            return Optional.of(STRICT.treeToValue(node, type));
        } catch (JsonMappingException e) {
            errors.add(pathOf(e, path, type), messageOf(e, node, names));
            return Optional.empty();
        } catch (RuntimeException | com.fasterxml.jackson.core.JsonProcessingException e) {
            errors.add(path, "cannot be read: " + e.getMessage());
            return Optional.empty();
        }
    }

    private static JsonNode withFilesResolved(JsonNode node, Class<? extends Record> type, java.nio.file.Path baseDir) {
        com.fasterxml.jackson.databind.node.ObjectNode copy = null;
        for (RecordComponent c : type.getRecordComponents()) {
            org.habla.plugin.Param p = c.getAnnotation(org.habla.plugin.Param.class);
            JsonNode v = node.get(jsonName(c));
            if (p == null || !p.file() || v == null || !v.isTextual() || v.asText().isBlank()) {
                continue;
            }
            java.nio.file.Path given = java.nio.file.Path.of(v.asText());
            if (!given.isAbsolute()) {
                copy = copy == null ? ((com.fasterxml.jackson.databind.node.ObjectNode) node).deepCopy() : copy;
                copy.put(jsonName(c), baseDir.resolve(given).normalize().toString());
            }
        }
        return copy == null ? node : copy;
    }

    /** The JSON key of each component of a params record, in declaration order. */
    static List<String> jsonNames(Class<? extends Record> type) {
        List<String> names = new ArrayList<>();
        for (RecordComponent c : type.getRecordComponents()) {
            names.add(jsonName(c));
        }
        return names;
    }

    static String jsonName(RecordComponent c) {
        return ParamDefaults.key(c);
    }

    private static JsonPath pathOf(JsonMappingException e, JsonPath base, Class<? extends Record> type) {
        JsonPath path = base;
        for (JsonMappingException.Reference r : e.getPath()) {
            if (r.getFieldName() != null) {
                path = path.field(r.getFieldName());
            } else if (r.getIndex() >= 0) {
                path = path.index(r.getIndex());
            }
        }
        if (e instanceof ValueInstantiationException && path.equals(base)) {
            Optional<String> named = namedComponent(rootMessage(e), jsonNames(type));
            if (named.isPresent()) {
                path = base.field(named.get());
            }
        }
        return path;
    }

    private static String messageOf(JsonMappingException e, JsonNode params, List<String> names) {
        if (e instanceof ValueInstantiationException) {
            Throwable cause = e.getCause() == null ? e : e.getCause();
            if (cause instanceof NullPointerException && cause.getMessage() != null && names.contains(cause.getMessage())) {
                return "required parameter '" + cause.getMessage() + "' is missing";
            }
            return rootMessage(e);
        }
        if (e instanceof UnrecognizedPropertyException u) {
            List<String> knownIds = u.getKnownPropertyIds() == null ? List.of()
                    : u.getKnownPropertyIds().stream().map(String::valueOf).toList();
            return "unknown parameter '" + u.getPropertyName() + "' (" + known(knownIds) + ")";
        }
        if (e instanceof InvalidNullException) {
            return "must not be null";
        }
        if (e instanceof MismatchedInputException m && m.getTargetType() != null) {
            return "must be " + expected(m.getTargetType()) + ", not " + CheckedObject.describe(valueAt(params, e));
        }
        return e.getOriginalMessage();
    }

    private static String rootMessage(Throwable e) {
        Throwable t = e;
        while (t.getCause() != null && t.getCause() != t) {
            t = t.getCause();
        }
        return t.getMessage() == null ? t.getClass().getSimpleName() : t.getMessage();
    }

    /** The one parameter a constructor's message names as a whole word, if exactly one. */
    private static Optional<String> namedComponent(String message, List<String> names) {
        List<String> hits = names.stream()
                .filter(n -> Pattern.compile("(?<![A-Za-z0-9_])" + Pattern.quote(n) + "(?![A-Za-z0-9_])")
                        .matcher(message).find())
                .toList();
        return hits.size() == 1 ? Optional.of(hits.get(0)) : Optional.empty();
    }

    private static JsonNode valueAt(JsonNode params, JsonMappingException e) {
        JsonNode at = params;
        for (JsonMappingException.Reference r : e.getPath()) {
            if (at == null) {
                return null;
            }
            at = r.getFieldName() != null ? at.get(r.getFieldName()) : at.get(r.getIndex());
        }
        return at;
    }

    /** How a Java type reads in a message: "an integer", "a number", "one of a, b". */
    static String expected(Class<?> t) {
        if (t == int.class || t == long.class || t == short.class || t == byte.class || t == Integer.class
                || t == Long.class || t == Short.class || t == Byte.class || t == java.math.BigInteger.class) {
            return "an integer";
        }
        if (t == double.class || t == float.class || t == Double.class || t == Float.class
                || t == java.math.BigDecimal.class) {
            return "a number";
        }
        if (t == boolean.class || t == Boolean.class) {
            return "a boolean (true or false)";
        }
        if (t == String.class || t == char.class || t == Character.class) {
            return "a string";
        }
        if (t.isEnum()) {
            TreeSet<String> values = new TreeSet<>();
            for (Object c : t.getEnumConstants()) {
                values.add(c.toString());
            }
            return "one of " + String.join(", ", values);
        }
        if (t.isArray() || Collection.class.isAssignableFrom(t)) {
            return "an array";
        }
        return "an object";
    }

    private static String known(List<String> names) {
        return names.isEmpty() ? "this type takes no parameters" : "known: " + String.join(", ", new TreeSet<>(names));
    }
}
