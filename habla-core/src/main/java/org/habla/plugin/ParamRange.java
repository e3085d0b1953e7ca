package org.habla.plugin;

import java.util.Optional;

/**
 * The range a number parameter declares in its {@link Param} annotation: checked by the config loader, shown by
 * {@code habla plugins} and written into the config schema.
 *
 * @param min         the least value, inclusive (minus infinity: none)
 * @param max         the greatest value, inclusive (plus infinity: none)
 * @param greaterThan a bound the value must exceed (minus infinity: none)
 */
public record ParamRange(double min, double max, double greaterThan) {

    /** The range {@code doc} declares, or empty when it declares none. */
    public static Optional<ParamRange> of(Param doc) {
        if (doc == null) {
            return Optional.empty();
        }
        ParamRange r = new ParamRange(doc.min(), doc.max(), doc.greaterThan());
        return r.bounded() ? Optional.of(r) : Optional.empty();
    }

    private boolean bounded() {
        return min != Double.NEGATIVE_INFINITY || max != Double.POSITIVE_INFINITY
                || greaterThan != Double.NEGATIVE_INFINITY;
    }

    /**
     * Why {@code value} is outside the range, or null when it is inside. {@code written} is the value as the config
     * wrote it, for the message.
     */
    public String refusal(double value, String written) {
        if (!Double.isFinite(value)) {
            return "must be a finite number, was " + written;
        }
        if (greaterThan != Double.NEGATIVE_INFINITY && !(value > greaterThan)) {
            return "must be greater than " + format(greaterThan) + ", was " + written;
        }
        if (value < min || value > max) {
            return "must be " + this + ", was " + written;
        }
        return null;
    }

    /** The range in words: {@code within [0, 1]}, {@code at least 0}, {@code greater than 0}, {@code at most 5}. */
    @Override
    public String toString() {
        boolean low = min != Double.NEGATIVE_INFINITY;
        boolean high = max != Double.POSITIVE_INFINITY;
        String above = greaterThan == Double.NEGATIVE_INFINITY ? "" : "greater than " + format(greaterThan);
        String bounds = low && high ? "within [" + format(min) + ", " + format(max) + "]"
                : low ? "at least " + format(min) : high ? "at most " + format(max) : "";
        return above.isEmpty() ? bounds : bounds.isEmpty() ? above : above + " and " + bounds;
    }

    /** A bound as people write it: {@code 1} rather than {@code 1.0}. */
    public static String format(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
