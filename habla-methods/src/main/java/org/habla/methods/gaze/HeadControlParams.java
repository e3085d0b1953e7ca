package org.habla.methods.gaze;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code head-control} method: what to follow, how briskly, how to search, and the joint limits. */
public record HeadControlParams(
        @Param(value = "Blob label to keep in view; empty follows the largest blob of any label", defaultValue = "\"pink\"")
        String label,
        @Param(value = "Share of the angular error corrected per image", defaultValue = "0.6",
                min = 0, max = 1)
        double gain,
        @Param(value = "Errors smaller than this are left alone", unit = "rad", defaultValue = "0.02",
                min = 0, max = 1)
        double deadbandRad,
        @Param(value = "Horizontal field of view; overrides the camera record", unit = "rad",
                defaultNote = "camera record", min = 0.01, max = 3.1)
        Double hfovRad,
        @Param(value = "Vertical field of view; overrides the camera record", unit = "rad",
                defaultNote = "camera record", min = 0.01, max = 3.1)
        Double vfovRad,
        @Param(value = "Time without the target after which the head starts scanning", unit = "ms",
                defaultValue = "1000", min = 0, max = 600_000)
        int lostAfterMs,
        @Param(value = "Pan speed of the scan", unit = "rad/s", defaultValue = "0.6",
                min = 0, max = 10)
        double scanSpeedRadps,
        @Param(value = "The scan sweeps the pan between minus and plus this", unit = "rad", defaultValue = "1.2",
                min = 0, max = Math.PI)
        double scanPanRad,
        @Param(value = "Neck tilt held during the scan", unit = "rad", defaultValue = "-0.35",
                min = -Math.PI, max = Math.PI)
        double scanTiltRad,
        @Param(value = "Nod held while tracking and scanning", unit = "rad", defaultValue = "0",
                min = -Math.PI, max = Math.PI)
        double nodRad,
        @Param(value = "Period of the scan steps", unit = "ms", defaultValue = "100",
                min = 10, max = 10_000)
        int periodMs,
        @Param(value = "Lowest neck tilt", unit = "rad", defaultValue = "-1.31",
                min = -Math.PI, max = Math.PI)
        double tiltMinRad,
        @Param(value = "Highest neck tilt", unit = "rad", defaultValue = "0.05",
                min = -Math.PI, max = Math.PI)
        double tiltMaxRad,
        @Param(value = "Pan furthest to the right", unit = "rad", defaultValue = "-1.62",
                min = -Math.PI, max = Math.PI)
        double panMinRad,
        @Param(value = "Pan furthest to the left", unit = "rad", defaultValue = "1.62",
                min = -Math.PI, max = Math.PI)
        double panMaxRad,
        @Param(value = "Lowest nod", unit = "rad", defaultValue = "-0.26",
                min = -Math.PI, max = Math.PI)
        double nodMinRad,
        @Param(value = "Highest nod", unit = "rad", defaultValue = "0.79",
                min = -Math.PI, max = Math.PI)
        double nodMaxRad) {

    public HeadControlParams {
        new HeadLimits(tiltMinRad, tiltMaxRad, panMinRad, panMaxRad, nodMinRad, nodMaxRad);
    }

    /** The head's joint limits these params give. */
    public HeadLimits limits() {
        return new HeadLimits(tiltMinRad, tiltMaxRad, panMinRad, panMaxRad, nodMinRad, nodMaxRad);
    }

    /** Every parameter at its default. */
    public static HeadControlParams defaults() {
        return ParamsJson.defaults(HeadControlParams.class);
    }
}
