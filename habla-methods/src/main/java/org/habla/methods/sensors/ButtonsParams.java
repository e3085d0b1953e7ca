package org.habla.methods.sensors;

import java.util.List;
import org.habla.methods.ParamRules;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/** The params of the {@code buttons} method: when a button counts as pressed and which buttons to watch. */
public record ButtonsParams(
        @Param(value = "A button whose value reaches this is pressed", defaultValue = "0.5") Double threshold,
        @Param(value = "A pressed button is released when its value falls below this (hysteresis)",
                defaultNote = "threshold × 0.6")
        Double releaseThreshold,
        @Param(value = "Names of the buttons to watch; empty watches every number in the record", defaultValue = "[]")
        List<String> names) {

    public ButtonsParams {
        threshold = ParamRules.within(ButtonsParams.class, "threshold", threshold, 1e-6, 1e9);
        releaseThreshold = ParamRules.within("releaseThreshold", releaseThreshold, threshold * 0.6, 0, threshold);
        names = List.copyOf(ParamDefaults.or(ButtonsParams.class, "names", names));
    }

    /** Every parameter at its default. */
    public static ButtonsParams defaults() {
        return new ButtonsParams(null, null, null);
    }
}
