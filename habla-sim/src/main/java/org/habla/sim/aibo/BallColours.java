package org.habla.sim.aibo;

import java.util.Locale;
import java.util.Map;

/**
 * The display colours of the world file's target colour names, saturated so that colour segmentation
 * finds them: pink {@code #FF50AA} (the paper's ball), orange, yellow, green, blue; any other name is pink.
 */
final class BallColours {

    private static final Map<String, Integer> RGB = Map.of(
            "pink", 0xff50aa, "orange", 0xff8020, "yellow", 0xf0e020, "green", 0x20c040, "blue", 0x2050ff);

    private BallColours() {
    }

    static int rgb(String name) {
        return RGB.getOrDefault(name == null ? "pink" : name.toLowerCase(Locale.ROOT), RGB.get("pink"));
    }
}
