package org.habla.methods.sensors;

import org.habla.config.ParamsJson;
import org.habla.methods.gaze.HeadLimits;
import org.habla.plugin.Param;

/**
 * The params of the {@code head} method: the head's joint limits. Each one left out comes from the
 * metadata of the channel input {@code pose} is wired to, then from a Sony ERS-7's head.
 */
public record HeadParams(
        @Param(value = "Lowest neck tilt (looking down)", unit = "rad", defaultNote = "channel metadata, else -1.31",
                min = -Math.PI, max = Math.PI)
        Double tiltMinRad,
        @Param(value = "Highest neck tilt", unit = "rad", defaultNote = "channel metadata, else 0.05",
                min = -Math.PI, max = Math.PI)
        Double tiltMaxRad,
        @Param(value = "Pan furthest to the right", unit = "rad", defaultNote = "channel metadata, else -1.62",
                min = -Math.PI, max = Math.PI)
        Double panMinRad,
        @Param(value = "Pan furthest to the left", unit = "rad", defaultNote = "channel metadata, else 1.62",
                min = -Math.PI, max = Math.PI)
        Double panMaxRad,
        @Param(value = "Lowest nod (looking down)", unit = "rad", defaultNote = "channel metadata, else -0.26",
                min = -Math.PI, max = Math.PI)
        Double nodMinRad,
        @Param(value = "Highest nod (looking up)", unit = "rad", defaultNote = "channel metadata, else 0.79",
                min = -Math.PI, max = Math.PI)
        Double nodMaxRad) implements HeadLimits.HeadLimitsOverride {

    public HeadParams {
        // Checked now so a bad value is reported against the config, not at start.
        HeadLimits.ofGiven(tiltMinRad, tiltMaxRad, panMinRad, panMaxRad, nodMinRad, nodMaxRad);
    }

    /** Every parameter left to the metadata and the defaults. */
    public static HeadParams defaults() {
        return ParamsJson.defaults(HeadParams.class);
    }
}
