package org.habla.drivers.lines;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of a {@code text-lines} interface. The charset is always UTF-8. */
public record TextLinesParams(
        @Param(value = "Longest line accepted, without its line end; longer lines are dropped and counted",
                unit = "byte", defaultValue = "1024", min = 1, max = MAX_LINE_BYTES)
        int maxLineBytes) {

    /** The largest {@code maxLineBytes} allowed. */
    public static final int MAX_LINE_BYTES = 1 << 20;


    public static TextLinesParams defaults() {
        return ParamsJson.defaults(TextLinesParams.class);
    }
}
