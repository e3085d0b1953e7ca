package org.example.habla;

import org.habla.plugin.Param;

/** The parameters of {@link Threshold}; the constructor fills defaults and validates. */
public record ThresholdParams(
        @Param(value = "below this the label becomes near", unit = "m", defaultValue = "0.5") Double nearM,
        @Param(value = "above this the label becomes far", unit = "m", defaultValue = "0.8") Double farM) {

    public ThresholdParams {
        nearM = nearM == null ? 0.5 : nearM;
        farM = farM == null ? 0.8 : farM;
        if (!(nearM < farM)) {
            throw new IllegalArgumentException("nearM (" + nearM + ") must be below farM (" + farM + ")");
        }
    }
}
