package org.habla.methods.perception;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code nearest-distance} method. */
public record NearestDistanceParams(
        @Param(value = "Readings shorter than this are ignored (cross-talk, a sensor touching something)", unit = "m",
                defaultValue = "0.02", min = 0)
        double minValidM,
        @Param(value = "Half-width of the cones ahead and behind the robot that aheadM and behindM cover", unit = "rad",
                defaultValue = "1.0471975511965976", min = 0.0, max = Math.PI)
        double coneRad,
        @Param(value = "A scan older than this is left out when several inputs are combined", unit = "ms",
                defaultValue = "1000", min = 1, max = 600_000)
        int maxAgeMs,
        @Param(value = "Neighbouring sensors whose readings are within this of the nearest are taken as seeing the "
                + "same object: its bearing is the mean of their points", unit = "m", defaultValue = "0.1", min = 0)
        double spreadM) {

    /** Every parameter at its default. */
    public static NearestDistanceParams defaults() {
        return ParamsJson.defaults(NearestDistanceParams.class);
    }
}
