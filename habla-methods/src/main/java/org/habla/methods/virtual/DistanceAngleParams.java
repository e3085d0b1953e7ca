package org.habla.methods.virtual;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code distance-angle} method: how often it speaks and when a target counts as lost. */
public record DistanceAngleParams(
        @Param(value = "How many records a second the method emits", unit = "Hz", defaultValue = "10")
        Double rateHz,
        @Param(value = "With no fresh sighting for this long the target is reported not seen", unit = "ms",
                defaultValue = "1000")
        Integer lostAfterMs) {

    public DistanceAngleParams {
        rateHz = ParamRules.within(DistanceAngleParams.class, "rateHz", rateHz, 0.1, 100.0);
        lostAfterMs = ParamRules.within(DistanceAngleParams.class, "lostAfterMs", lostAfterMs, 1, 600_000);
    }

    /** Every parameter at its default. */
    public static DistanceAngleParams defaults() {
        return new DistanceAngleParams(null, null);
    }
}
