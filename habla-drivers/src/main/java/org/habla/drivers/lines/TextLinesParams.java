package org.habla.drivers.lines;

import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/** The params of a {@code text-lines} interface. The charset is always UTF-8. */
public record TextLinesParams(
        @Param(value = "Longest line accepted, without its line end; longer lines are dropped and counted",
                unit = "byte", defaultValue = "1024")
        Integer maxLineBytes) {

    /** The largest {@code maxLineBytes} allowed. */
    public static final int MAX_LINE_BYTES = 1 << 20;

    public TextLinesParams {
        maxLineBytes = ParamDefaults.or(TextLinesParams.class, "maxLineBytes", maxLineBytes);
        if (maxLineBytes < 1 || maxLineBytes > MAX_LINE_BYTES) {
            throw new IllegalArgumentException("maxLineBytes must be in 1.." + MAX_LINE_BYTES + ", was " + maxLineBytes);
        }
    }

    public static TextLinesParams defaults() {
        return new TextLinesParams(null);
    }
}
