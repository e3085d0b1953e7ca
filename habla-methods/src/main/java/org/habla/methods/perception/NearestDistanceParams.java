package org.habla.methods.perception;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code nearest-distance} method. */
public record NearestDistanceParams(
        @Param(value = "Readings shorter than this are ignored (cross-talk, a sensor touching something)", unit = "m",
                defaultValue = "0.02")
        Double minValidM,
        @Param(value = "Half-width of the cones ahead and behind the robot that aheadM and behindM cover", unit = "rad",
                defaultValue = "1.0471975511965976")
        Double coneRad,
        @Param(value = "A scan older than this is left out when several inputs are combined", unit = "ms",
                defaultValue = "1000")
        Integer maxAgeMs,
        @Param(value = "Neighbouring sensors whose readings are within this of the nearest are taken as seeing the "
                + "same object: its bearing is the mean of their points", unit = "m", defaultValue = "0.1")
        Double spreadM) {

    public NearestDistanceParams {
        minValidM = ParamRules.nonNegative(NearestDistanceParams.class, "minValidM", minValidM);
        coneRad = ParamRules.within(NearestDistanceParams.class, "coneRad", coneRad, 0.0, Math.PI);
        maxAgeMs = ParamRules.within(NearestDistanceParams.class, "maxAgeMs", maxAgeMs, 1, 600_000);
        spreadM = ParamRules.nonNegative(NearestDistanceParams.class, "spreadM", spreadM);
    }

    /** Every parameter at its default. */
    public static NearestDistanceParams defaults() {
        return new NearestDistanceParams(null, null, null, null);
    }
}
