package org.habla.methods.motion;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code movement-safety} method: how close an obstacle may come, and the top speeds. */
public record MovementSafetyParams(
        @Param(value = "Forward (backward) motion is vetoed while an obstacle ahead (behind) is nearer than this",
                unit = "m", defaultValue = "0.3")
        Double stopDistanceM,
        @Param(value = "Half-width of the cones ahead and behind, used when the nearest record has no aheadM/behindM",
                unit = "rad", defaultValue = "1.0471975511965976")
        Double coneRad,
        @Param(value = "With no nearest record for this long, forward and backward motion are vetoed", unit = "ms",
                defaultValue = "1000")
        Integer maxAgeMs,
        @Param(value = "Highest forward or backward speed; overrides the limits input", unit = "m/s",
                defaultNote = "the limits input, else no limit")
        Double maxVelMps,
        @Param(value = "Highest turn rate; overrides the limits input", unit = "rad/s",
                defaultNote = "the limits input, else no limit")
        Double maxRotVelRadps) {

    public MovementSafetyParams {
        stopDistanceM = ParamRules.nonNegative(MovementSafetyParams.class, "stopDistanceM", stopDistanceM);
        coneRad = ParamRules.within(MovementSafetyParams.class, "coneRad", coneRad, 0.0, Math.PI);
        maxAgeMs = ParamRules.within(MovementSafetyParams.class, "maxAgeMs", maxAgeMs, 1, 600_000);
        maxVelMps = ParamRules.positiveOrNull("maxVelMps", maxVelMps);
        maxRotVelRadps = ParamRules.positiveOrNull("maxRotVelRadps", maxRotVelRadps);
    }

    /** Every parameter at its default. */
    public static MovementSafetyParams defaults() {
        return new MovementSafetyParams(null, null, null, null, null);
    }
}
