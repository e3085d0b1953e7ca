package org.habla.methods.position;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/**
 * The params of the {@code coordinate-translation} method. The camera's geometry is best left out:
 * it then comes from the {@code camera} record of the camera method (the channel's metadata).
 */
public record CoordinateTranslationParams(
        @Param(value = "Blob label of the target object; empty takes the largest blob of any label", defaultValue = "\"pink\"")
        String label,
        @Param(value = "Radius of the target object (a ball)", unit = "m", defaultValue = "0.05")
        Double targetRadiusM,
        @Param(value = "Horizontal field of view; overrides the camera record", unit = "rad", defaultNote = "camera record")
        Double hfovRad,
        @Param(value = "Vertical field of view; overrides the camera record", unit = "rad", defaultNote = "camera record")
        Double vfovRad,
        @Param(value = "Height of the camera above the floor; overrides the camera record", unit = "m",
                defaultNote = "camera record")
        Double cameraHeightM,
        @Param(value = "How far ahead of the robot's origin the camera's pan axis sits", unit = "m", defaultValue = "0")
        Double cameraXM,
        @Param(value = "How far ahead of the pan axis the lens sits, along the pan direction", unit = "m",
                defaultValue = "0")
        Double lensForwardM,
        @Param(value = "Radius of the robot's body: distanceM is measured from the body's edge", unit = "m",
                defaultValue = "0")
        Double bodyRadiusM,
        @Param(value = "Below this apparent radius the size estimate gives way to the ground-plane one", unit = "px",
                defaultValue = "1.5")
        Double minRadiusPx) {

    public CoordinateTranslationParams {
        label = ParamDefaults.or(CoordinateTranslationParams.class, "label", label);
        targetRadiusM = ParamRules.positive(CoordinateTranslationParams.class, "targetRadiusM", targetRadiusM);
        hfovRad = ParamRules.withinOrNull("hfovRad", hfovRad, 0.01, 3.1);
        vfovRad = ParamRules.withinOrNull("vfovRad", vfovRad, 0.01, 3.1);
        cameraHeightM = ParamRules.nonNegativeOrNull("cameraHeightM", cameraHeightM);
        cameraXM = ParamRules.within(CoordinateTranslationParams.class, "cameraXM", cameraXM, -10, 10);
        lensForwardM = ParamRules.within(CoordinateTranslationParams.class, "lensForwardM", lensForwardM, -10, 10);
        bodyRadiusM = ParamRules.within(CoordinateTranslationParams.class, "bodyRadiusM", bodyRadiusM, 0, 10);
        minRadiusPx = ParamRules.nonNegative(CoordinateTranslationParams.class, "minRadiusPx", minRadiusPx);
    }

    /** Every parameter at its default. */
    public static CoordinateTranslationParams defaults() {
        return new CoordinateTranslationParams(null, null, null, null, null, null, null, null, null);
    }
}
