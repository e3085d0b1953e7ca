package org.habla.methods.sensors;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code odometry} method. */
public record OdometryParams(
        @Param(value = "Report the pose relative to where the robot was at the first reading", defaultValue = "false")
        boolean fromFirstReading) {

    /** Every parameter at its default. */
    public static OdometryParams defaults() {
        return ParamsJson.defaults(OdometryParams.class);
    }
}
