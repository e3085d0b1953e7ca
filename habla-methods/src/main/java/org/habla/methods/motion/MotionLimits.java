package org.habla.methods.motion;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Optional;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;

/**
 * The top speeds of a mobile base: forward/backward speed and turn rate. They come from the metadata of a
 * robot's motion channel ({@code "maxVelMps"}, {@code "maxRotVelRadps"}), from params, or from the
 * {@code limits} record a {@code wheels} method publishes; {@link #NONE} when nothing is known.
 *
 * @param maxVelMps      highest |v|, m/s; infinite when unknown
 * @param maxRotVelRadps highest |w|, rad/s; infinite when unknown
 */
public record MotionLimits(double maxVelMps, double maxRotVelRadps) implements RecordForm {

    /** The fields of a limits record; an unknown limit is left out. */
    public static final RecordLayout<MotionLimits> LAYOUT = RecordLayout.of(MotionLimits.class)
            .optionalNumber("maxVelMps", l -> Double.isFinite(l.maxVelMps) ? l.maxVelMps : null).unit("m/s")
            .doc("highest forward or backward speed; absent when unknown")
            .optionalNumber("maxRotVelRadps", l -> Double.isFinite(l.maxRotVelRadps) ? l.maxRotVelRadps : null)
            .unit("rad/s").doc("highest turn rate; absent when unknown")
            .build();

    /** No limit known. */
    public static final MotionLimits NONE = new MotionLimits(Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY);

    public MotionLimits {
        if (!(maxVelMps > 0) || !(maxRotVelRadps > 0)) {
            throw new IllegalArgumentException("motion limits must be positive, were " + maxVelMps + ", " + maxRotVelRadps);
        }
    }

    /** Reads {@code maxVelMps} and {@code maxRotVelRadps} where present and positive; empty if neither is. */
    public static Optional<MotionLimits> fromJson(JsonNode node) {
        double v = positive(node.path("maxVelMps"));
        double w = positive(node.path("maxRotVelRadps"));
        if (Double.isInfinite(v) && Double.isInfinite(w)) {
            return Optional.empty();
        }
        return Optional.of(new MotionLimits(v, w));
    }

    /** These limits with each one the params give put in its place. */
    public MotionLimits overriddenBy(Double paramMaxVelMps, Double paramMaxRotVelRadps) {
        return new MotionLimits(paramMaxVelMps != null ? paramMaxVelMps : maxVelMps,
                paramMaxRotVelRadps != null ? paramMaxRotVelRadps : maxRotVelRadps);
    }

    /**
     * {@code [v, w]} scaled down by one common factor until both are within the limits, so a curved path keeps
     * its curvature and only gets slower.
     */
    public double[] clamp(double vMps, double wRadps) {
        double scale = 1;
        if (Math.abs(vMps) > maxVelMps) {
            scale = Math.min(scale, maxVelMps / Math.abs(vMps));
        }
        if (Math.abs(wRadps) > maxRotVelRadps) {
            scale = Math.min(scale, maxRotVelRadps / Math.abs(wRadps));
        }
        return new double[] {vMps * scale, wRadps * scale};
    }

    /** The {@code limits} record; an unknown limit is left out. */
    public RecordValue toRecord() {
        return RecordValue.of(this);
    }

    @Override
    public RecordLayout<MotionLimits> layout() {
        return LAYOUT;
    }

    /** The limits a {@code limits} record carries; {@link #NONE} when it gives none. */
    public static MotionLimits fromRecord(RecordValue record) {
        return record.as(MotionLimits.class, r -> fromJson(r.jsonView()).orElse(NONE));
    }

    /**
     * A motion {@code [vMps, wRadps]} read from a vector; empty unless it has exactly two finite elements.
     */
    public static Optional<double[]> motionOf(VectorValue value) {
        if (value.size() != 2 || !Double.isFinite(value.get(0)) || !Double.isFinite(value.get(1))) {
            return Optional.empty();
        }
        return Optional.of(new double[] {value.get(0), value.get(1)});
    }

    private static double positive(JsonNode n) {
        return n.isNumber() && n.doubleValue() > 0 && Double.isFinite(n.doubleValue())
                ? n.doubleValue() : Double.POSITIVE_INFINITY;
    }
}
