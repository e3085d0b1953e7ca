package org.habla.methods;

/**
 * The checks params records apply in their compact constructors: each fills in a default for a
 * missing (null) value and throws an {@link IllegalArgumentException} naming the parameter when the
 * value is out of bounds.
 */
public final class ParamRules {

    private ParamRules() {
    }

    /** A finite number greater than zero. */
    public static double positive(String name, Double value, double fallback) {
        double v = value == null ? fallback : value;
        if (!(v > 0) || !Double.isFinite(v)) {
            throw new IllegalArgumentException(name + " must be a positive number, was " + value);
        }
        return v;
    }

    /** A finite number of at least zero. */
    public static double nonNegative(String name, Double value, double fallback) {
        double v = value == null ? fallback : value;
        if (!(v >= 0) || !Double.isFinite(v)) {
            throw new IllegalArgumentException(name + " must be a number of at least 0, was " + value);
        }
        return v;
    }

    /** A finite number within [min, max]. */
    public static double within(String name, Double value, double fallback, double min, double max) {
        double v = value == null ? fallback : value;
        if (!(v >= min && v <= max)) {
            throw new IllegalArgumentException(name + " must be within [" + min + ", " + max + "], was " + value);
        }
        return v;
    }

    /** A whole number within [min, max]. */
    public static int within(String name, Integer value, int fallback, int min, int max) {
        int v = value == null ? fallback : value;
        if (v < min || v > max) {
            throw new IllegalArgumentException(name + " must be within " + min + ".." + max + ", was " + value);
        }
        return v;
    }

    /** A positive number, or null when the parameter is left to the channel's metadata. */
    public static Double positiveOrNull(String name, Double value) {
        return value == null ? null : positive(name, value, 0);
    }
}
