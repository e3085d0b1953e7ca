package org.habla.methods.locomotion;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code gait-composition} method: how a planar motion becomes a walk, and the walk limits. */
public record GaitCompositionParams(
        @Param(value = "Factor applied to the motion's forward speed", defaultValue = "1",
                min = 0, max = 100)
        double forwardScale,
        @Param(value = "Factor applied to the motion's turn rate", defaultValue = "1",
                min = 0, max = 100)
        double rotateScale,
        @Param(value = "Fastest forward walk", unit = "m/s", defaultValue = "0.18",
                min = 0, max = 10)
        double maxForwardMps,
        @Param(value = "Fastest backward walk", unit = "m/s", defaultValue = "0.18",
                min = 0, max = 10)
        double maxReverseMps,
        @Param(value = "Fastest sideways walk", unit = "m/s", defaultValue = "0.14",
                min = 0, max = 10)
        double maxStrafeMps,
        @Param(value = "Fastest turn", unit = "rad/s", defaultValue = "1.8", min = 0, max = 20) double maxRotateRadps,
        @Param(value = "Share of a turn walked sideways instead (0: turn on the spot; 1: pure strafe)",
                defaultValue = "0", min = 0, max = 1)
        double strafeShare,
        @Param(value = "Sideways speed of a full strafe share, per rad/s of turn", unit = "m/s per rad/s",
                defaultValue = "0.1", min = 0, max = 10)
        double strafeMpsPerRadps) {

    /** Every parameter at its default. */
    public static GaitCompositionParams defaults() {
        return ParamsJson.defaults(GaitCompositionParams.class);
    }

    public WalkLimits limits() {
        return new WalkLimits(maxForwardMps, maxReverseMps, maxStrafeMps, maxRotateRadps);
    }
}
