package org.habla.methods.sensors;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code keyboard} method. */
public record KeyboardParams(
        @Param(value = "Longest line handed on; longer lines are cut to it", unit = "characters", defaultValue = "256",
                min = 1, max = 65_536)
        int maxLength) {

    /** Every parameter at its default. */
    public static KeyboardParams defaults() {
        return ParamsJson.defaults(KeyboardParams.class);
    }
}
