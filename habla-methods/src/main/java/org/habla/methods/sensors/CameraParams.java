package org.habla.methods.sensors;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/**
 * The params of the {@code camera} method. The geometry is best left to the camera channel's
 * metadata ({@code hfovRad}, {@code vfovRad}, {@code heightM}); set it here for a channel that does not
 * describe its camera.
 */
public record CameraParams(
        @Param(value = "Most frames a second handed on; 0 hands on every frame", unit = "1/s", defaultValue = "0")
        Double maxFps,
        @Param(value = "Horizontal field of view; overrides the channel metadata", unit = "rad",
                defaultNote = "channel metadata")
        Double hfovRad,
        @Param(value = "Vertical field of view; overrides the channel metadata", unit = "rad",
                defaultNote = "channel metadata")
        Double vfovRad,
        @Param(value = "Height of the camera above the floor; overrides the channel metadata", unit = "m",
                defaultNote = "channel metadata, else 0")
        Double heightM) {

    public CameraParams {
        maxFps = ParamRules.within(CameraParams.class, "maxFps", maxFps, 0, 1000);
        hfovRad = ParamRules.withinOrNull("hfovRad", hfovRad, 0.01, 3.1);
        vfovRad = ParamRules.withinOrNull("vfovRad", vfovRad, 0.01, 3.1);
        heightM = ParamRules.withinOrNull("heightM", heightM, 0, 100);
    }

    /** Every parameter at its default. */
    public static CameraParams defaults() {
        return new CameraParams(null, null, null, null);
    }
}
