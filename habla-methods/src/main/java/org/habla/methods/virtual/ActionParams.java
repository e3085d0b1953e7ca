package org.habla.methods.virtual;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code action} method: the motion each label means and how long it is held. */
public record ActionParams(
        @Param(value = "Forward speed of the forward action", unit = "m/s", defaultValue = "0.2")
        Double forwardMps,
        @Param(value = "Backward speed of the back action (given as a positive number)", unit = "m/s",
                defaultValue = "0.15")
        Double backMps,
        @Param(value = "Turn rate of the left and right actions (given as a positive number)", unit = "rad/s",
                defaultValue = "0.6")
        Double turnRadps,
        @Param(value = "How long an action's motion is held before the motion returns to zero", unit = "ms",
                defaultValue = "1000")
        Integer durationMs) {

    public ActionParams {
        forwardMps = ParamRules.positive(ActionParams.class, "forwardMps", forwardMps);
        backMps = ParamRules.positive(ActionParams.class, "backMps", backMps);
        turnRadps = ParamRules.positive(ActionParams.class, "turnRadps", turnRadps);
        durationMs = ParamRules.within(ActionParams.class, "durationMs", durationMs, 1, 60_000);
    }

    /** Every parameter at its default. */
    public static ActionParams defaults() {
        return new ActionParams(null, null, null, null);
    }
}
