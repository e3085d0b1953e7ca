package org.habla.methods.sensors;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.methods.geometry.PlanarPose;
import org.habla.plugin.Param;

/**
 * The params of the {@code sonar} and {@code infrared} methods. Every geometry parameter is optional:
 * left out, it comes from the channel's metadata ({@code maxRangeM}, {@code minRangeM}, {@code poses}),
 * so one config works for every robot whose driver describes its sensors.
 */
public record RangeSensorParams(
        @Param(value = "Reach of every sensor; overrides the channel metadata", unit = "m",
                defaultNote = "channel metadata, else 5.0 (sonar) or 1.5 (infrared)", greaterThan = 0)
        Double maxRangeM,
        @Param(value = "Shortest range the sensors measure; closer readings are raised to it", unit = "m",
                defaultNote = "channel metadata, else 0", min = 0)
        Double minRangeM,
        @Param(value = "Sensor poses [{xM, yM, thetaRad}] in index order; overrides the channel metadata",
                unit = "m, rad", defaultNote = "channel metadata")
        List<PlanarPose> poses,
        @Param(value = "Turn sensors mounted on the head (metadata mount = head) by the head's pan when input head is wired",
                defaultValue = "true")
        boolean panWithHead) {

    public RangeSensorParams {
        if (minRangeM != null) {
            if (maxRangeM != null && minRangeM >= maxRangeM) {
                throw new IllegalArgumentException("minRangeM must be below maxRangeM, was " + minRangeM);
            }
        }
        if (poses != null && (poses.isEmpty() || poses.size() > 256)) {
            throw new IllegalArgumentException("poses must list 1..256 poses, has " + poses.size());
        }
        poses = poses == null ? null : List.copyOf(poses);
    }

    /** Every parameter at its default. */
    public static RangeSensorParams defaults() {
        return ParamsJson.defaults(RangeSensorParams.class);
    }
}
