package org.habla.methods.virtual;

import java.util.Map;
import org.habla.methods.ParamRules;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/** The params of the {@code command} method: which heard input means which command label. */
public record CommandParams(
        @Param(value = "Heard input (a note name or a recognised phrase, matched ignoring case and extra spaces) "
                + "→ command label",
                defaultValue = "{\"C5\":\"forward\",\"E5\":\"left\",\"G5\":\"right\",\"C6\":\"back\","
                        + "\"go forward\":\"forward\",\"turn left\":\"left\",\"turn right\":\"right\",\"go back\":\"back\"}")
        Map<String, String> map,
        @Param(value = "The same label again within this time is taken as the same command and dropped", unit = "ms",
                defaultValue = "0")
        Integer debounceMs) {

    public CommandParams {
        map = Map.copyOf(ParamDefaults.or(CommandParams.class, "map", map));
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
        debounceMs = ParamRules.within(CommandParams.class, "debounceMs", debounceMs, 0, 600_000);
    }

    /** Every parameter at its default. */
    public static CommandParams defaults() {
        return new CommandParams(null, null);
    }
}
