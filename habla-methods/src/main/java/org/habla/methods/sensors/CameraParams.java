package org.habla.methods.sensors;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/**
 * The params of the {@code camera} method. The geometry is best left to the camera channel's
 * metadata ({@code hfovRad}, {@code vfovRad}, {@code heightM}); set it here for a channel that does not
 * describe its camera.
 */
public record CameraParams(
        @Param(value = "Most frames a second handed on; 0 hands on every frame", unit = "1/s", defaultValue = "0",
                min = 0, max = 1000)
        double maxFps,
        @Param(value = "Horizontal field of view; overrides the channel metadata", unit = "rad",
                defaultNote = "channel metadata", min = 0.01, max = 3.1)
        Double hfovRad,
        @Param(value = "Vertical field of view; overrides the channel metadata", unit = "rad",
                defaultNote = "channel metadata", min = 0.01, max = 3.1)
        Double vfovRad,
        @Param(value = "Height of the camera above the floor; overrides the channel metadata", unit = "m",
                defaultNote = "channel metadata, else 0", min = 0, max = 100)
        Double heightM) {

    /** Every parameter at its default. */
    public static CameraParams defaults() {
        return ParamsJson.defaults(CameraParams.class);
    }
}
