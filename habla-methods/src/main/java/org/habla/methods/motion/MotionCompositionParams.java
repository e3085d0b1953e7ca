package org.habla.methods.motion;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code motion-composition} method: how fast the base may change speed, and its top speeds. */
public record MotionCompositionParams(
        @Param(value = "Largest rise of |v| per second", unit = "m/s²", defaultValue = "0.5")
        Double maxAccelMps2,
        @Param(value = "Largest fall of |v| per second (braking)", unit = "m/s²", defaultValue = "1.0")
        Double maxDecelMps2,
        @Param(value = "Largest change of the turn rate per second", unit = "rad/s²", defaultValue = "2.0")
        Double maxRotAccelRadps2,
        @Param(value = "Highest forward or backward speed; overrides the limits input", unit = "m/s",
                defaultNote = "the limits input, else no limit")
        Double maxVelMps,
        @Param(value = "Highest turn rate; overrides the limits input", unit = "rad/s",
                defaultNote = "the limits input, else no limit")
        Double maxRotVelRadps,
        @Param(value = "Period of the ramp steps", unit = "ms", defaultValue = "50")
        Integer tickMs) {

    public MotionCompositionParams {
        maxAccelMps2 = ParamRules.positive(MotionCompositionParams.class, "maxAccelMps2", maxAccelMps2);
        maxDecelMps2 = ParamRules.positive(MotionCompositionParams.class, "maxDecelMps2", maxDecelMps2);
        maxRotAccelRadps2 = ParamRules.positive(MotionCompositionParams.class, "maxRotAccelRadps2", maxRotAccelRadps2);
        maxVelMps = ParamRules.positiveOrNull("maxVelMps", maxVelMps);
        maxRotVelRadps = ParamRules.positiveOrNull("maxRotVelRadps", maxRotVelRadps);
        tickMs = ParamRules.within(MotionCompositionParams.class, "tickMs", tickMs, 5, 1000);
    }

    /** Every parameter at its default. */
    public static MotionCompositionParams defaults() {
        return new MotionCompositionParams(null, null, null, null, null, null);
    }
}
