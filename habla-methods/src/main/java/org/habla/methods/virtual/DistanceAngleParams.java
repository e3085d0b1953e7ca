package org.habla.methods.virtual;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code distance-angle} method: how often it speaks and when a target counts as lost. */
public record DistanceAngleParams(
        @Param(value = "How many records a second the method emits", unit = "Hz", defaultValue = "10",
                min = 0.1, max = 100.0)
        double rateHz,
        @Param(value = "With no fresh sighting for this long the target is reported not seen", unit = "ms",
                defaultValue = "1000", min = 1, max = 600_000)
        int lostAfterMs) {

    /** Every parameter at its default. */
    public static DistanceAngleParams defaults() {
        return ParamsJson.defaults(DistanceAngleParams.class);
    }
}
