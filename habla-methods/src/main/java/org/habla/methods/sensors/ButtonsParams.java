package org.habla.methods.sensors;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code buttons} method: when a button counts as pressed and which buttons to watch. */
public record ButtonsParams(
        @Param(value = "A button whose value reaches this is pressed", defaultValue = "0.5",
                min = 1e-6, max = 1e9)
        double threshold,
        @Param(value = "A pressed button is released when its value falls below this (hysteresis)",
                defaultNote = "threshold × 0.6", min = 0)
        Double releaseThreshold,
        @Param(value = "Names of the buttons to watch; empty watches every number in the record", defaultValue = "[]")
        List<String> names) {

    public ButtonsParams {
        releaseThreshold = releaseThreshold == null ? threshold * 0.6 : releaseThreshold;
        if (releaseThreshold > threshold) {
            throw new IllegalArgumentException("releaseThreshold must not exceed threshold (" + threshold + "), was "
                    + releaseThreshold);
        }
        names = List.copyOf(names);
    }

    /** Every parameter at its default. */
    public static ButtonsParams defaults() {
        return ParamsJson.defaults(ButtonsParams.class);
    }
}
