package org.habla.methods;


/**
 * The checks params records apply in their compact constructors: each throws an
 * {@link IllegalArgumentException} naming the parameter when the value is out of bounds. A null (from
 * Java code; the config loader has already filled left-out keys) takes the default the record declares in
 * its {@link org.habla.plugin.Param} annotation, so the default is written only there.
 */
public final class ParamRules {

    private ParamRules() {
    }

    /** A finite number greater than zero; null takes the declared default. */
    public static double positive(Class<? extends Record> params, String name, Double value) {
        return positive(name, or(params, name, value));
    }

    /** A finite number of at least zero; null takes the declared default. */
    public static double nonNegative(Class<? extends Record> params, String name, Double value) {
        return nonNegative(name, or(params, name, value));
    }

    /** A finite number within [min, max]; null takes the declared default. */
    public static double within(Class<? extends Record> params, String name, Double value, double min, double max) {
        return within(name, or(params, name, value), min, max);
    }

    /** A whole number within [min, max]; null takes the declared default. */
    public static int within(Class<? extends Record> params, String name, Integer value, int min, int max) {
        return within(name, or(params, name, value), min, max);
    }

    /**
     * A finite number within [min, max], or {@code fallback} when null: for a default computed from other
     * parameters, which an annotation cannot state.
     */
    public static double within(String name, Double value, double fallback, double min, double max) {
        return within(name, value == null ? fallback : value, min, max);
    }

    /** A positive number, or null when the parameter is left to the channel's metadata. */
    public static Double positiveOrNull(String name, Double value) {
        return value == null ? null : positive(name, value);
    }

    /** A number of at least zero, or null when the parameter is left to the channel's metadata. */
    public static Double nonNegativeOrNull(String name, Double value) {
        return value == null ? null : nonNegative(name, value);
    }

    /** A number within [min, max], or null when the parameter is left to the channel's metadata. */
    public static Double withinOrNull(String name, Double value, double min, double max) {
        return value == null ? null : within(name, value, min, max);
    }

    /** {@code value}, or when null the default {@code params} declares for {@code name}. */
    @SuppressWarnings("unchecked")
    public static <T> T or(Class<? extends Record> params, String name, T value) {
        if (value != null) {
            return value;
        }
        for (java.lang.reflect.RecordComponent c : params.getRecordComponents()) {
            if (c.getName().equals(name)) {
                com.fasterxml.jackson.databind.JsonNode d = org.habla.plugin.ParamDefaults.json(params, c)
                        .orElseThrow(() -> new IllegalArgumentException(name + " is required"));
                return (T) JSON.convertValue(d, JSON.constructType(c.getGenericType()));
            }
        }
        throw new IllegalArgumentException(params.getName() + " has no parameter " + name);
    }

    private static final com.fasterxml.jackson.databind.ObjectMapper JSON = new com.fasterxml.jackson.databind.ObjectMapper();

    private static double positive(String name, double v) {
        if (!(v > 0) || !Double.isFinite(v)) {
            throw new IllegalArgumentException(name + " must be a positive number, was " + v);
        }
        return v;
    }

    private static double nonNegative(String name, double v) {
        if (!(v >= 0) || !Double.isFinite(v)) {
            throw new IllegalArgumentException(name + " must be a number of at least 0, was " + v);
        }
        return v;
    }

    private static double within(String name, double v, double min, double max) {
        if (!(v >= min && v <= max)) {
            throw new IllegalArgumentException(name + " must be within [" + min + ", " + max + "], was " + v);
        }
        return v;
    }

    private static int within(String name, int v, int min, int max) {
        if (v < min || v > max) {
            throw new IllegalArgumentException(name + " must be within " + min + ".." + max + ", was " + v);
        }
        return v;
    }
}
