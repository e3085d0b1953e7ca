package org.habla.methods.virtual;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code link-state} method. */
public record LinkStateParams(
        @Param(value = "With no link record for this long the state is reported stale (the engine sends one a second)",
                unit = "ms", defaultValue = "3000", min = 100, max = 600_000)
        int staleAfterMs) {

    /** Every parameter at its default. */
    public static LinkStateParams defaults() {
        return ParamsJson.defaults(LinkStateParams.class);
    }
}
