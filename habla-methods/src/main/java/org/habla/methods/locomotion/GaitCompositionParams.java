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
        forwardScale = ParamRules.within(GaitCompositionParams.class, "forwardScale", forwardScale, 0, 100);
        rotateScale = ParamRules.within(GaitCompositionParams.class, "rotateScale", rotateScale, 0, 100);
        maxForwardMps = ParamRules.within(GaitCompositionParams.class, "maxForwardMps", maxForwardMps, 0, 10);
        maxReverseMps = ParamRules.within(GaitCompositionParams.class, "maxReverseMps", maxReverseMps, 0, 10);
        maxStrafeMps = ParamRules.within(GaitCompositionParams.class, "maxStrafeMps", maxStrafeMps, 0, 10);
        maxRotateRadps = ParamRules.within(GaitCompositionParams.class, "maxRotateRadps", maxRotateRadps, 0, 20);
        strafeShare = ParamRules.within(GaitCompositionParams.class, "strafeShare", strafeShare, 0, 1);
        strafeMpsPerRadps = ParamRules.within(GaitCompositionParams.class, "strafeMpsPerRadps", strafeMpsPerRadps, 0, 10);
    }

    /** Every parameter at its default. */
    public static GaitCompositionParams defaults() {
        return new GaitCompositionParams(null, null, null, null, null, null, null, null);
    }

    public WalkLimits limits() {
        return new WalkLimits(maxForwardMps, maxReverseMps, maxStrafeMps, maxRotateRadps);
    }
}
