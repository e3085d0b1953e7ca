package org.habla.methods.motion;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code motion-composition} method: how fast the base may change speed, and its top speeds. */
public record MotionCompositionParams(
        @Param(value = "Largest rise of |v| per second", unit = "m/s²", defaultValue = "0.5", greaterThan = 0)
        double maxAccelMps2,
        @Param(value = "Largest fall of |v| per second (braking)", unit = "m/s²", defaultValue = "1.0", greaterThan = 0)
        double maxDecelMps2,
        @Param(value = "Largest change of the turn rate per second", unit = "rad/s²", defaultValue = "2.0",
                greaterThan = 0)
        double maxRotAccelRadps2,
        @Param(value = "Highest forward or backward speed; overrides the limits input", unit = "m/s",
                defaultNote = "the limits input, else no limit", greaterThan = 0)
        Double maxVelMps,
        @Param(value = "Highest turn rate; overrides the limits input", unit = "rad/s",
                defaultNote = "the limits input, else no limit", greaterThan = 0)
        Double maxRotVelRadps,
        @Param(value = "Period of the ramp steps", unit = "ms", defaultValue = "50", min = 5, max = 1000)
        int tickMs) {

    /** Every parameter at its default. */
    public static MotionCompositionParams defaults() {
        return ParamsJson.defaults(MotionCompositionParams.class);
    }
}
