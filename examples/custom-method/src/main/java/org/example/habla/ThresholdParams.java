package org.example.habla;

import org.habla.plugin.Param;

/**
 * The parameters of {@link Threshold}: defaults and ranges come from the annotations (the config loader fills and
 * checks them), the constructor checks the rule between the two.
 */
public record ThresholdParams(
        @Param(value = "below this the label becomes near", unit = "m", defaultValue = "0.5", min = 0) double nearM,
        @Param(value = "above this the label becomes far", unit = "m", defaultValue = "0.8", min = 0) double farM) {

    public ThresholdParams {
        if (!(nearM < farM)) {
            throw new IllegalArgumentException("nearM (" + nearM + ") must be below farM (" + farM + ")");
        }
    }
}
