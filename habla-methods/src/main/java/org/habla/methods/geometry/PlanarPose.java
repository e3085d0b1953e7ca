package org.habla.methods.geometry;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Optional;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * A position and heading in the plane of the robot frame: x forward, y to the left, theta
 * counter-clockwise from x. Used for sensor mounts and robot poses.
 *
 * @param xM       forward, in metres
 * @param yM       to the left, in metres
 * @param thetaRad heading, in radians, within (-π, π]
 */
public record PlanarPose(double xM, double yM, double thetaRad) implements RecordForm {

    /** The fields of a pose record. */
    public static final RecordLayout<PlanarPose> LAYOUT = RecordLayout.of(PlanarPose.class)
            .number("xM", PlanarPose::xM).unit("m").frame("the pose's frame: x forward, y to the left").doc("forward")
            .number("yM", PlanarPose::yM).unit("m").frame("the pose's frame: x forward, y to the left").doc("to the left")
            .number("thetaRad", PlanarPose::thetaRad).unit("rad").frame("counter-clockwise from x, within (-π, π]")
            .doc("heading")
            .build();

    public static final PlanarPose ORIGIN = new PlanarPose(0, 0, 0);

    public PlanarPose {
        if (!Double.isFinite(xM) || !Double.isFinite(yM) || !Double.isFinite(thetaRad)) {
            throw new IllegalArgumentException("a pose needs finite xM, yM and thetaRad, was " + xM + ", " + yM + ", " + thetaRad);
        }
        thetaRad = wrap(thetaRad);
    }

    /** An angle brought into (-π, π]. */
    public static double wrap(double rad) {
        double a = Math.IEEEremainder(rad, 2 * Math.PI);
        return a <= -Math.PI ? a + 2 * Math.PI : a;
    }

    /** The point {@code rangeM} ahead of this pose, along its heading turned by {@code bearingRad}. */
    public double[] pointAt(double rangeM, double bearingRad) {
        double a = thetaRad + bearingRad;
        return new double[] {xM + rangeM * Math.cos(a), yM + rangeM * Math.sin(a)};
    }

    /** This pose turned by {@code panRad} about the origin's vertical axis (a sensor on a panning head). */
    public PlanarPose turnedAboutOrigin(double panRad) {
        double c = Math.cos(panRad);
        double s = Math.sin(panRad);
        return new PlanarPose(c * xM - s * yM, s * xM + c * yM, thetaRad + panRad);
    }

    /** Reads {@code {"xM","yM","thetaRad"}}; empty if a field is missing or not a finite number. */
    public static Optional<PlanarPose> fromJson(JsonNode node) {
        return fromFields(node.path("xM"), node.path("yM"), node.path("thetaRad"));
    }

    private static Optional<PlanarPose> fromFields(JsonNode x, JsonNode y, JsonNode t) {
        if (!x.isNumber() || !y.isNumber() || !t.isNumber()) {
            return Optional.empty();
        }
        double xv = x.doubleValue();
        double yv = y.doubleValue();
        double tv = t.doubleValue();
        if (!Double.isFinite(xv) || !Double.isFinite(yv) || !Double.isFinite(tv)) {
            return Optional.empty();
        }
        return Optional.of(new PlanarPose(xv, yv, tv));
    }

    /**
     * The pose a record carries: itself, or read from its fields as {@link #fromJson} does (through the record's
     * accessors, so a reading typed by a driver makes no JSON).
     */
    public static Optional<PlanarPose> fromRecord(RecordValue record) {
        Optional<PlanarPose> typed = record.form(PlanarPose.class);
        return typed.isPresent() ? typed : fromFields(record.get("xM"), record.get("yM"), record.get("thetaRad"));
    }

    /** A {@code pose} record carrying this pose. */
    public RecordValue toRecord() {
        return RecordValue.of(this);
    }

    @Override
    public RecordLayout<PlanarPose> layout() {
        return LAYOUT;
    }
}
