package org.habla.methods.virtual;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code action} method: the motion each label means and how long it is held. */
public record ActionParams(
        @Param(value = "Forward speed of the forward action", unit = "m/s", defaultValue = "0.2", greaterThan = 0)
        double forwardMps,
        @Param(value = "Backward speed of the back action (given as a positive number)", unit = "m/s",
                defaultValue = "0.15", greaterThan = 0)
        double backMps,
        @Param(value = "Turn rate of the left and right actions (given as a positive number)", unit = "rad/s",
                defaultValue = "0.6", greaterThan = 0)
        double turnRadps,
        @Param(value = "How long an action's motion is held before the motion returns to zero", unit = "ms",
                defaultValue = "1000", min = 1, max = 60_000)
        int durationMs) {

    /** Every parameter at its default. */
    public static ActionParams defaults() {
        return ParamsJson.defaults(ActionParams.class);
    }
}
