package org.habla.methods.virtual;

import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;

/**
 * The {@code distance_angle} record of {@code distance-angle}: how far the target is, its bearing, and whether it
 * is perceived now (else the figures are the last sighting's).
 *
 * <pre>{@code {"distanceM": 0.8, "angleRad": 0.12, "seen": true}}</pre>
 */
public record TargetBearing(double distanceM, double angleRad, boolean seen) implements RecordForm {

    /** The fields of a distance_angle record. */
    public static final RecordLayout<TargetBearing> LAYOUT = RecordLayout.of(TargetBearing.class)
            .number("distanceM", TargetBearing::distanceM).unit("m")
            .frame("as the input measures it: from the range sensor (nearest), or from the robot's edge to the "
                    + "target's edge (position)")
            .doc("how far the target is")
            .number("angleRad", TargetBearing::angleRad).unit("rad")
            .frame("robot frame: from the robot's centre, positive to the left").doc("the target's bearing")
            .flag("seen", TargetBearing::seen).doc("whether the target is perceived now; else the last sighting's figures")
            .build();

    @Override
    public RecordLayout<TargetBearing> layout() {
        return LAYOUT;
    }
}
