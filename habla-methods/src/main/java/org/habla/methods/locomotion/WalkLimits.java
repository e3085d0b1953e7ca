package org.habla.methods.locomotion;

import java.util.Optional;
import org.habla.sample.VectorValue;

/**
 * The fastest a walking robot may go: forward, backward, sideways and turning. A walk command is the
 * vector {@code [forwardMps, strafeMps, rotateRadps]} (strafe positive to the left, rotation positive
 * counter-clockwise).
 */
public record WalkLimits(double maxForwardMps, double maxReverseMps, double maxStrafeMps, double maxRotateRadps) {

    public WalkLimits {
        if (!(maxForwardMps >= 0) || !(maxReverseMps >= 0) || !(maxStrafeMps >= 0) || !(maxRotateRadps >= 0)
                || !Double.isFinite(maxForwardMps + maxReverseMps + maxStrafeMps + maxRotateRadps)) {
            throw new IllegalArgumentException("walk limits must be finite and not negative");
        }
    }

    /** Each component brought within its limit on its own. */
    public double[] clamp(double forward, double strafe, double rotate) {
        return new double[] {
            Math.max(-maxReverseMps, Math.min(maxForwardMps, forward)),
            Math.max(-maxStrafeMps, Math.min(maxStrafeMps, strafe)),
            Math.max(-maxRotateRadps, Math.min(maxRotateRadps, rotate))};
    }

    /**
     * The command shrunk as a whole until every component is within its limit: the robot walks the
     * same curve, only slower.
     */
    public double[] scale(double forward, double strafe, double rotate) {
        double f = 1;
        f = Math.min(f, ratio(forward, forward >= 0 ? maxForwardMps : maxReverseMps));
        f = Math.min(f, ratio(strafe, maxStrafeMps));
        f = Math.min(f, ratio(rotate, maxRotateRadps));
        return new double[] {forward * f, strafe * f, rotate * f};
    }

    private static double ratio(double value, double max) {
        return Math.abs(value) <= max ? 1 : max / Math.abs(value);
    }

    /**
     * Reads a walk vector: three finite numbers, or two ({@code [forward, rotate]}, no strafe). Empty
     * when it is neither.
     */
    public static Optional<double[]> read(VectorValue v) {
        double[] a;
        if (v.size() == 3) {
            a = v.toArray();
        } else if (v.size() == 2) {
            a = new double[] {v.get(0), 0, v.get(1)};
        } else {
            return Optional.empty();
        }
        for (double x : a) {
            if (!Double.isFinite(x)) {
                return Optional.empty();
            }
        }
        return Optional.of(a);
    }
}
