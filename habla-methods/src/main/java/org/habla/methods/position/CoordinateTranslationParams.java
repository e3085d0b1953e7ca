package org.habla.methods.position;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

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
        label = label == null ? "pink" : label;
        targetRadiusM = ParamRules.positive("targetRadiusM", targetRadiusM, 0.05);
        hfovRad = hfovRad == null ? null : ParamRules.within("hfovRad", hfovRad, 1, 0.01, 3.1);
        vfovRad = vfovRad == null ? null : ParamRules.within("vfovRad", vfovRad, 1, 0.01, 3.1);
        cameraHeightM = cameraHeightM == null ? null : ParamRules.nonNegative("cameraHeightM", cameraHeightM, 0);
        cameraXM = ParamRules.within("cameraXM", cameraXM, 0, -10, 10);
        lensForwardM = ParamRules.within("lensForwardM", lensForwardM, 0, -10, 10);
        bodyRadiusM = ParamRules.within("bodyRadiusM", bodyRadiusM, 0, 0, 10);
        minRadiusPx = ParamRules.nonNegative("minRadiusPx", minRadiusPx, 1.5);
    }

    /** Every parameter at its default. */
    public static CoordinateTranslationParams defaults() {
        return new CoordinateTranslationParams(null, null, null, null, null, null, null, null, null);
    }
}
