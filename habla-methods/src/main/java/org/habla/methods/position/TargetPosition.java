package org.habla.methods.position;

import com.fasterxml.jackson.databind.JsonNode;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * The {@code position} record of {@code coordinate-translation}: where the target is in the robot frame, whether
 * it is perceived now, how it was placed, and where it is in the odometry frame when the robot's pose is known.
 *
 * <pre>{@code {"xM": 1.2, "yM": 0.3, "distanceM": 1.0, "angleRad": 0.24, "seen": true, "method": "size",
 *   "xWorldM": 3.1, "yWorldM": -0.4}}</pre>
 *
 * Read from JSON (a socket, a recording, a worker), a number the record lacks is NaN and a missing {@code seen} is
 * false.
 *
 * @param method       how a camera fix was made ({@code size} or {@code ground}), or null when not by camera
 * @param groundRangeM the range the ground fix gave, or null
 * @param xWorldM      the target in the odometry frame, or null when the robot's pose is unknown
 * @param yWorldM      the target in the odometry frame, or null when the robot's pose is unknown
 */
public record TargetPosition(double xM, double yM, double distanceM, double angleRad, boolean seen, String method,
        Double groundRangeM, Double xWorldM, Double yWorldM) implements RecordForm {

    private static final String ROBOT_FRAME = "robot frame: from the robot's centre, x forward, y to the left";

    /** The fields of a position record. */
    public static final RecordLayout<TargetPosition> LAYOUT = RecordLayout.of(TargetPosition.class)
            .number("xM", TargetPosition::xM).unit("m").frame(ROBOT_FRAME).doc("the target's centre, forward")
            .number("yM", TargetPosition::yM).unit("m").frame(ROBOT_FRAME).doc("the target's centre, to the left")
            .number("distanceM", TargetPosition::distanceM).unit("m")
            .frame("camera: from the robot's edge to the target's edge; nearest: the range sensor's own reading")
            .doc("how far the target is")
            .number("angleRad", TargetPosition::angleRad).unit("rad")
            .frame("robot frame: from the robot's centre, positive to the left").doc("the target's bearing")
            .flag("seen", TargetPosition::seen).doc("whether the target is perceived now; else the last sighting")
            .text("method", TargetPosition::method).optional().doc("how a camera fix was made: size or ground")
            .optionalNumber("groundRangeM", TargetPosition::groundRangeM).unit("m")
            .frame("from the camera, along the ground").doc("the range the ground fix gave")
            .optionalNumber("xWorldM", TargetPosition::xWorldM).unit("m").frame("odometry frame")
            .doc("the target in the odometry frame, when the robot's pose is known")
            .optionalNumber("yWorldM", TargetPosition::yWorldM).unit("m").frame("odometry frame")
            .doc("the target in the odometry frame, when the robot's pose is known")
            .build();

    @Override
    public RecordLayout<TargetPosition> layout() {
        return LAYOUT;
    }

    /** The position a record carries: the form itself inside the daemon, else read from its JSON. */
    public static TargetPosition fromRecord(RecordValue record) {
        return record.as(TargetPosition.class, TargetPosition::read);
    }

    private static TargetPosition read(RecordValue r) {
        JsonNode seen = r.get("seen");
        JsonNode method = r.get("method");
        return new TargetPosition(number(r.get("xM")), number(r.get("yM")), number(r.get("distanceM")),
                number(r.get("angleRad")), seen.isBoolean() && seen.booleanValue(),
                method.isTextual() ? method.textValue() : null, optional(r.get("groundRangeM")),
                optional(r.get("xWorldM")), optional(r.get("yWorldM")));
    }

    private static double number(JsonNode n) {
        return n.isNumber() && Double.isFinite(n.doubleValue()) ? n.doubleValue() : Double.NaN;
    }

    private static Double optional(JsonNode n) {
        return n.isNumber() ? n.doubleValue() : null;
    }
}
