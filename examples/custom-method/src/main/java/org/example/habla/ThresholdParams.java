package org.example.habla;

import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/** The parameters of {@link Threshold}; defaults come from the annotations, the constructor validates. */
public record ThresholdParams(
        @Param(value = "below this the label becomes near", unit = "m", defaultValue = "0.5") Double nearM,
        @Param(value = "above this the label becomes far", unit = "m", defaultValue = "0.8") Double farM) {

    public ThresholdParams {
        nearM = ParamDefaults.or(ThresholdParams.class, "nearM", nearM);
        farM = ParamDefaults.or(ThresholdParams.class, "farM", farM);
        if (!(nearM < farM)) {
            throw new IllegalArgumentException("nearM (" + nearM + ") must be below farM (" + farM + ")");
        }
    }
}
