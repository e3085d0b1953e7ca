package org.habla.methods.virtual;

import java.util.Map;
import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code reward} method: which words and which touches mean pleasure or pain. */
public record RewardParams(
        @Param(value = "Text (matched ignoring case and extra spaces) → reward in [-1, 1]; a number such as +1 or "
                + "-0.5 is read as itself",
                defaultValue = "{\"pleasure\":1,\"pain\":-1,\"good dog\":1,\"well done\":1,\"bad dog\":-1,\"no\":-1}")
        Map<String, Double> words,
        @Param(value = "Touch sensor field of the buttons record → reward in [-1, 1] when it is pressed",
                defaultValue = "{\"backMiddle\":1,\"headTouch\":-1}")
        Map<String, Double> touch,
        @Param(value = "A touch sensor reads as pressed at or above this value (booleans: true)",
                defaultValue = "0.5", min = 1e-6, max = 1e6)
        double threshold) {

    public RewardParams {
        words = checked("words", words);
        touch = checked("touch", touch);
    }

    /** Every parameter at its default. */
    public static RewardParams defaults() {
        return ParamsJson.defaults(RewardParams.class);
    }

    private static Map<String, Double> checked(String name, Map<String, Double> map) {
        if (map.size() > 1024) {
            throw new IllegalArgumentException(name + " may hold at most 1024 entries, has " + map.size());
        }
        for (Map.Entry<String, Double> e : map.entrySet()) {
            Double v = e.getValue();
            if (e.getKey().isBlank() || v == null || !(v >= -1 && v <= 1)) {
                throw new IllegalArgumentException(name + " entry '" + e.getKey() + "' needs a reward within [-1, 1], was " + v);
            }
        }
        return Map.copyOf(map);
    }
}
