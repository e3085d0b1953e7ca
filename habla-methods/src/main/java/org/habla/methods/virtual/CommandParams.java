package org.habla.methods.virtual;

import java.util.Map;
import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code command} method: which heard input means which command label. */
public record CommandParams(
        @Param(value = "Heard input (a note name or a recognised phrase, matched ignoring case and extra spaces) "
                + "→ command label",
                defaultValue = "{\"C5\":\"forward\",\"E5\":\"left\",\"G5\":\"right\",\"C6\":\"back\","
                        + "\"go forward\":\"forward\",\"turn left\":\"left\",\"turn right\":\"right\",\"go back\":\"back\"}")
        Map<String, String> map,
        @Param(value = "The same label again within this time is taken as the same command and dropped", unit = "ms",
                defaultValue = "0", min = 0, max = 600_000)
        int debounceMs) {

    public CommandParams {
        map = Map.copyOf(map);
        if (map.isEmpty() || map.size() > 1024) {
            throw new IllegalArgumentException("map must hold 1..1024 entries, has " + map.size());
        }
        for (Map.Entry<String, String> e : map.entrySet()) {
            if (Command.key(e.getKey()).isEmpty() || e.getValue() == null || e.getValue().isBlank()
                    || e.getValue().length() > 64) {
                throw new IllegalArgumentException("map entry '" + e.getKey() + "' needs a non-blank input and a label "
                        + "of 1..64 characters, has '" + e.getValue() + "'");
            }
        }
    }

    /** Every parameter at its default. */
    public static CommandParams defaults() {
        return ParamsJson.defaults(CommandParams.class);
    }
}
