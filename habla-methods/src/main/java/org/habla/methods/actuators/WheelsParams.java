package org.habla.methods.actuators;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code wheels} method: speed limits that override the motion channel's metadata. */
public record WheelsParams(
        @Param(value = "Highest forward or backward speed; overrides the channel metadata maxVelMps", unit = "m/s",
                defaultNote = "channel metadata, else no limit", greaterThan = 0)
        Double maxVelMps,
        @Param(value = "Highest turn rate; overrides the channel metadata maxRotVelRadps", unit = "rad/s",
                defaultNote = "channel metadata, else no limit", greaterThan = 0)
        Double maxRotVelRadps) {

    /** Every parameter at its default. */
    public static WheelsParams defaults() {
        return ParamsJson.defaults(WheelsParams.class);
    }
}
