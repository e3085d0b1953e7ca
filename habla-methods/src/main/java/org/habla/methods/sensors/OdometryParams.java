package org.habla.methods.sensors;

import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/** The params of the {@code odometry} method. */
public record OdometryParams(
        @Param(value = "Report the pose relative to where the robot was at the first reading", defaultValue = "false")
        Boolean fromFirstReading) {

    public OdometryParams {
        fromFirstReading = ParamDefaults.or(OdometryParams.class, "fromFirstReading", fromFirstReading);
    }

    /** Every parameter at its default. */
    public static OdometryParams defaults() {
        return new OdometryParams(null);
    }
}
