package org.habla.methods.position;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/**
 * The params of the {@code coordinate-translation} method. The camera's geometry is best left out:
 * it then comes from the {@code camera} record of the camera method (the channel's metadata).
 */
public record CoordinateTranslationParams(
        @Param(value = "Blob label of the target object; empty takes the largest blob of any label", defaultValue = "\"pink\"")
        String label,
        @Param(value = "Radius of the target object (a ball)", unit = "m", defaultValue = "0.05", greaterThan = 0)
        double targetRadiusM,
        @Param(value = "Horizontal field of view; overrides the camera record", unit = "rad",
                defaultNote = "camera record", min = 0.01, max = 3.1)
        Double hfovRad,
        @Param(value = "Vertical field of view; overrides the camera record", unit = "rad",
                defaultNote = "camera record", min = 0.01, max = 3.1)
        Double vfovRad,
        @Param(value = "Height of the camera above the floor; overrides the camera record", unit = "m",
                defaultNote = "camera record", min = 0)
        Double cameraHeightM,
        @Param(value = "How far ahead of the robot's origin the camera's pan axis sits", unit = "m", defaultValue = "0",
                min = -10, max = 10)
        double cameraXM,
        @Param(value = "How far ahead of the pan axis the lens sits, along the pan direction", unit = "m",
                defaultValue = "0", min = -10, max = 10)
        double lensForwardM,
        @Param(value = "Radius of the robot's body: distanceM is measured from the body's edge", unit = "m",
                defaultValue = "0", min = 0, max = 10)
        double bodyRadiusM,
        @Param(value = "Below this apparent radius the size estimate gives way to the ground-plane one", unit = "px",
                defaultValue = "1.5", min = 0)
        double minRadiusPx) {

    /** Every parameter at its default. */
    public static CoordinateTranslationParams defaults() {
        return ParamsJson.defaults(CoordinateTranslationParams.class);
    }
}
