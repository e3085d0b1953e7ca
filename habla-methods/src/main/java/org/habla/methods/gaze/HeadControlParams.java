package org.habla.methods.gaze;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/** The params of the {@code head-control} method: what to follow, how briskly, how to search, and the joint limits. */
public record HeadControlParams(
        @Param(value = "Blob label to keep in view; empty follows the largest blob of any label", defaultValue = "\"pink\"")
        String label,
        @Param(value = "Share of the angular error corrected per image", defaultValue = "0.6") Double gain,
        @Param(value = "Errors smaller than this are left alone", unit = "rad", defaultValue = "0.02") Double deadbandRad,
        @Param(value = "Horizontal field of view; overrides the camera record", unit = "rad", defaultNote = "camera record")
        Double hfovRad,
        @Param(value = "Vertical field of view; overrides the camera record", unit = "rad", defaultNote = "camera record")
        Double vfovRad,
        @Param(value = "Time without the target after which the head starts scanning", unit = "ms", defaultValue = "1000")
        Integer lostAfterMs,
        @Param(value = "Pan speed of the scan", unit = "rad/s", defaultValue = "0.6") Double scanSpeedRadps,
        @Param(value = "The scan sweeps the pan between minus and plus this", unit = "rad", defaultValue = "1.2")
        Double scanPanRad,
        @Param(value = "Neck tilt held during the scan", unit = "rad", defaultValue = "-0.35") Double scanTiltRad,
        @Param(value = "Nod held while tracking and scanning", unit = "rad", defaultValue = "0") Double nodRad,
        @Param(value = "Period of the scan steps", unit = "ms", defaultValue = "100") Integer periodMs,
        @Param(value = "Lowest neck tilt", unit = "rad", defaultValue = "-1.31") Double tiltMinRad,
        @Param(value = "Highest neck tilt", unit = "rad", defaultValue = "0.05") Double tiltMaxRad,
        @Param(value = "Pan furthest to the right", unit = "rad", defaultValue = "-1.62") Double panMinRad,
        @Param(value = "Pan furthest to the left", unit = "rad", defaultValue = "1.62") Double panMaxRad,
        @Param(value = "Lowest nod", unit = "rad", defaultValue = "-0.26") Double nodMinRad,
        @Param(value = "Highest nod", unit = "rad", defaultValue = "0.79") Double nodMaxRad)
        implements HeadLimits.HeadLimitsOverride {

    public HeadControlParams {
        label = ParamDefaults.or(HeadControlParams.class, "label", label);
        gain = ParamRules.within(HeadControlParams.class, "gain", gain, 0, 1);
        deadbandRad = ParamRules.within(HeadControlParams.class, "deadbandRad", deadbandRad, 0, 1);
        hfovRad = ParamRules.withinOrNull("hfovRad", hfovRad, 0.01, 3.1);
        vfovRad = ParamRules.withinOrNull("vfovRad", vfovRad, 0.01, 3.1);
        lostAfterMs = ParamRules.within(HeadControlParams.class, "lostAfterMs", lostAfterMs, 0, 600_000);
        scanSpeedRadps = ParamRules.within(HeadControlParams.class, "scanSpeedRadps", scanSpeedRadps, 0, 10);
        scanPanRad = ParamRules.within(HeadControlParams.class, "scanPanRad", scanPanRad, 0, Math.PI);
        scanTiltRad = ParamRules.within(HeadControlParams.class, "scanTiltRad", scanTiltRad, -Math.PI, Math.PI);
        nodRad = ParamRules.within(HeadControlParams.class, "nodRad", nodRad, -Math.PI, Math.PI);
        periodMs = ParamRules.within(HeadControlParams.class, "periodMs", periodMs, 10, 10_000);
        tiltMinRad = ParamDefaults.or(HeadControlParams.class, "tiltMinRad", tiltMinRad);
        tiltMaxRad = ParamDefaults.or(HeadControlParams.class, "tiltMaxRad", tiltMaxRad);
        panMinRad = ParamDefaults.or(HeadControlParams.class, "panMinRad", panMinRad);
        panMaxRad = ParamDefaults.or(HeadControlParams.class, "panMaxRad", panMaxRad);
        nodMinRad = ParamDefaults.or(HeadControlParams.class, "nodMinRad", nodMinRad);
        nodMaxRad = ParamDefaults.or(HeadControlParams.class, "nodMaxRad", nodMaxRad);
        new HeadLimits(tiltMinRad, tiltMaxRad, panMinRad, panMaxRad, nodMinRad, nodMaxRad);
    }

    /** Every parameter at its default. */
    public static HeadControlParams defaults() {
        return new HeadControlParams(null, null, null, null, null, null, null, null, null, null, null,
                null, null, null, null, null, null);
    }
}
