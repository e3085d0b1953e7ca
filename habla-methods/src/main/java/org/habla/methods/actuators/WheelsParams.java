package org.habla.methods.actuators;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code wheels} method: speed limits that override the motion channel's metadata. */
public record WheelsParams(
        @Param(value = "Highest forward or backward speed; overrides the channel metadata maxVelMps", unit = "m/s",
                defaultNote = "channel metadata, else no limit")
        Double maxVelMps,
        @Param(value = "Highest turn rate; overrides the channel metadata maxRotVelRadps", unit = "rad/s",
                defaultNote = "channel metadata, else no limit")
        Double maxRotVelRadps) {

    public WheelsParams {
        maxVelMps = ParamRules.positiveOrNull("maxVelMps", maxVelMps);
        maxRotVelRadps = ParamRules.positiveOrNull("maxRotVelRadps", maxRotVelRadps);
    }

    /** Every parameter at its default. */
    public static WheelsParams defaults() {
        return new WheelsParams(null, null);
    }
}
