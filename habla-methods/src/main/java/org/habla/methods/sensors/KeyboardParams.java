package org.habla.methods.sensors;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code keyboard} method. */
public record KeyboardParams(
        @Param(value = "Longest line handed on; longer lines are cut to it", unit = "characters", defaultValue = "256")
        Integer maxLength) {

    public KeyboardParams {
        maxLength = ParamRules.within(KeyboardParams.class, "maxLength", maxLength, 1, 65_536);
    }

    /** Every parameter at its default. */
    public static KeyboardParams defaults() {
        return new KeyboardParams(null);
    }
}
