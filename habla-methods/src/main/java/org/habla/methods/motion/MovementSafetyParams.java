package org.habla.methods.motion;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code movement-safety} method: how close an obstacle may come, and the top speeds. */
public record MovementSafetyParams(
        @Param(value = "Forward (backward) motion is vetoed while an obstacle ahead (behind) is nearer than this",
                unit = "m", defaultValue = "0.3", min = 0)
        double stopDistanceM,
        @Param(value = "Half-width of the cones ahead and behind, used when the nearest record has no aheadM/behindM",
                unit = "rad", defaultValue = "1.0471975511965976", min = 0.0, max = Math.PI)
        double coneRad,
        @Param(value = "With no nearest record for this long, forward and backward motion are vetoed", unit = "ms",
                defaultValue = "1000", min = 1, max = 600_000)
        int maxAgeMs,
        @Param(value = "Highest forward or backward speed; overrides the limits input", unit = "m/s",
                defaultNote = "the limits input, else no limit", greaterThan = 0)
        Double maxVelMps,
        @Param(value = "Highest turn rate; overrides the limits input", unit = "rad/s",
                defaultNote = "the limits input, else no limit", greaterThan = 0)
        Double maxRotVelRadps) {

    /** Every parameter at its default. */
    public static MovementSafetyParams defaults() {
        return ParamsJson.defaults(MovementSafetyParams.class);
    }
}
