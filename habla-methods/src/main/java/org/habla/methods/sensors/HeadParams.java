package org.habla.methods.sensors;

import org.habla.methods.gaze.HeadLimits;
import org.habla.plugin.Param;

/**
 * The params of the {@code head} method: the head's joint limits. Each one left out comes from the
 * metadata of the channel input {@code pose} is wired to, then from a Sony ERS-7's head.
 */
public record HeadParams(
        @Param(value = "Lowest neck tilt (looking down)", unit = "rad", defaultNote = "channel metadata, else -1.31")
        Double tiltMinRad,
        @Param(value = "Highest neck tilt", unit = "rad", defaultNote = "channel metadata, else 0.05")
        Double tiltMaxRad,
        @Param(value = "Pan furthest to the right", unit = "rad", defaultNote = "channel metadata, else -1.62")
        Double panMinRad,
        @Param(value = "Pan furthest to the left", unit = "rad", defaultNote = "channel metadata, else 1.62")
        Double panMaxRad,
        @Param(value = "Lowest nod (looking down)", unit = "rad", defaultNote = "channel metadata, else -0.26")
        Double nodMinRad,
        @Param(value = "Highest nod (looking up)", unit = "rad", defaultNote = "channel metadata, else 0.79")
        Double nodMaxRad) implements HeadLimits.HeadLimitsOverride {

    public HeadParams {
        // Checked now so a bad value is reported against the config, not at start.
        new HeadLimits(tiltMinRad, tiltMaxRad, panMinRad, panMaxRad, nodMinRad, nodMaxRad);
    }

    /** Every parameter left to the metadata and the defaults. */
    public static HeadParams defaults() {
        return new HeadParams(null, null, null, null, null, null);
    }
}
