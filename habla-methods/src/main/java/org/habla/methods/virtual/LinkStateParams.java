package org.habla.methods.virtual;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code link-state} method. */
public record LinkStateParams(
        @Param(value = "With no link record for this long the state is reported stale (the engine sends one a second)",
                unit = "ms", defaultValue = "3000")
        Integer staleAfterMs) {

    public LinkStateParams {
        staleAfterMs = ParamRules.within(LinkStateParams.class, "staleAfterMs", staleAfterMs, 100, 600_000);
    }

    /** Every parameter at its default. */
    public static LinkStateParams defaults() {
        return new LinkStateParams(null);
    }
}
