package org.habla.sim.scenario;

import java.util.ArrayList;
import java.util.List;

/**
 * The tick marks of a plot axis: round values (1, 2 or 5 times a power of ten apart) covering a data range,
 * so an axis reads 0, 0.5, 1.0, 1.5 rather than 0, 0.37, 0.74.
 *
 * @param min  the first tick, at or below the data's minimum
 * @param max  the last tick, at or above the data's maximum
 * @param step the distance between ticks (&gt; 0)
 */
record Ticks(double min, double max, double step) {

    /** Ticks over [lo, hi] with about {@code count} intervals; an empty range is widened to show something. */
    static Ticks nice(double lo, double hi, int count) {
        if (!Double.isFinite(lo) || !Double.isFinite(hi) || hi < lo) {
            lo = 0;
            hi = 1;
        }
        if (hi - lo < 1e-9) {
            hi = lo + Math.max(1.0, Math.abs(lo));
        }
        double raw = (hi - lo) / Math.max(1, count);
        double power = Math.pow(10, Math.floor(Math.log10(raw)));
        double fraction = raw / power;
        double step = (fraction <= 1 ? 1 : fraction <= 2 ? 2 : fraction <= 5 ? 5 : 10) * power;
        return new Ticks(Math.floor(lo / step + 1e-9) * step, Math.ceil(hi / step - 1e-9) * step, step);
    }

    /** Every tick value from min to max. */
    List<Double> values() {
        List<Double> v = new ArrayList<>();
        long n = Math.round((max - min) / step);
        for (long i = 0; i <= n; i++) {
            v.add(min + i * step);
        }
        return v;
    }

    /** A tick's label, with only as many decimals as the step needs. */
    String label(double value) {
        int decimals = (int) Math.max(0, Math.ceil(-Math.log10(step) - 1e-9));
        return String.format(java.util.Locale.ROOT, "%." + decimals + "f", value);
    }
}
