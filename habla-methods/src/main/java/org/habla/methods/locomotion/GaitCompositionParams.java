package org.habla.methods.locomotion;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code gait-composition} method: how a planar motion becomes a walk, and the walk limits. */
public record GaitCompositionParams(
        @Param(value = "Factor applied to the motion's forward speed", defaultValue = "1") Double forwardScale,
        @Param(value = "Factor applied to the motion's turn rate", defaultValue = "1") Double rotateScale,
        @Param(value = "Fastest forward walk", unit = "m/s", defaultValue = "0.18") Double maxForwardMps,
        @Param(value = "Fastest backward walk", unit = "m/s", defaultValue = "0.18") Double maxReverseMps,
        @Param(value = "Fastest sideways walk", unit = "m/s", defaultValue = "0.14") Double maxStrafeMps,
        @Param(value = "Fastest turn", unit = "rad/s", defaultValue = "1.8") Double maxRotateRadps,
        @Param(value = "Share of a turn walked sideways instead (0: turn on the spot; 1: pure strafe)", defaultValue = "0")
        Double strafeShare,
        @Param(value = "Sideways speed of a full strafe share, per rad/s of turn", unit = "m/s per rad/s",
                defaultValue = "0.1")
        Double strafeMpsPerRadps) {

    public GaitCompositionParams {
        forwardScale = ParamRules.within("forwardScale", forwardScale, 1, 0, 100);
        rotateScale = ParamRules.within("rotateScale", rotateScale, 1, 0, 100);
        maxForwardMps = ParamRules.within("maxForwardMps", maxForwardMps, 0.18, 0, 10);
        maxReverseMps = ParamRules.within("maxReverseMps", maxReverseMps, 0.18, 0, 10);
        maxStrafeMps = ParamRules.within("maxStrafeMps", maxStrafeMps, 0.14, 0, 10);
        maxRotateRadps = ParamRules.within("maxRotateRadps", maxRotateRadps, 1.8, 0, 20);
        strafeShare = ParamRules.within("strafeShare", strafeShare, 0, 0, 1);
        strafeMpsPerRadps = ParamRules.within("strafeMpsPerRadps", strafeMpsPerRadps, 0.1, 0, 10);
    }

    /** Every parameter at its default. */
    public static GaitCompositionParams defaults() {
        return new GaitCompositionParams(null, null, null, null, null, null, null, null);
    }

    public WalkLimits limits() {
        return new WalkLimits(maxForwardMps, maxReverseMps, maxStrafeMps, maxRotateRadps);
    }
}
