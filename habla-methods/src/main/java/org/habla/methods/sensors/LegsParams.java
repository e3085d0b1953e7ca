package org.habla.methods.sensors;

import org.habla.methods.ParamRules;
import org.habla.methods.locomotion.WalkLimits;
import org.habla.plugin.Param;

/**
 * The params of the {@code legs} method: the walk limits commands are clamped to. Set them to the
 * robot's, as its walk channel's metadata states them ({@code maxForwardMps}, …); the defaults are
 * those of the Tekkotsu driver's defaults.
 */
public record LegsParams(
        @Param(value = "Fastest forward walk", unit = "m/s", defaultValue = "0.18") Double maxForwardMps,
        @Param(value = "Fastest backward walk", unit = "m/s", defaultValue = "0.18") Double maxReverseMps,
        @Param(value = "Fastest sideways walk", unit = "m/s", defaultValue = "0.14") Double maxStrafeMps,
        @Param(value = "Fastest turn", unit = "rad/s", defaultValue = "1.8") Double maxRotateRadps,
        @Param(value = "Queue length of the walk input, in commands", defaultValue = "8") Integer queue) {

    public LegsParams {
        maxForwardMps = ParamRules.within("maxForwardMps", maxForwardMps, 0.18, 0, 10);
        maxReverseMps = ParamRules.within("maxReverseMps", maxReverseMps, 0.18, 0, 10);
        maxStrafeMps = ParamRules.within("maxStrafeMps", maxStrafeMps, 0.14, 0, 10);
        maxRotateRadps = ParamRules.within("maxRotateRadps", maxRotateRadps, 1.8, 0, 20);
        queue = ParamRules.within("queue", queue, 8, 1, 1024);
    }

    /** Every parameter at its default. */
    public static LegsParams defaults() {
        return new LegsParams(null, null, null, null, null);
    }

    public WalkLimits limits() {
        return new WalkLimits(maxForwardMps, maxReverseMps, maxStrafeMps, maxRotateRadps);
    }
}
