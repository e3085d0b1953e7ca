package org.habla.methods.vision;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/**
 * One colour class of {@code image-segmentation}: a box in OpenCV's HSV space (hue 0..179, saturation
 * and value 0..255). When {@code hMin} is greater than {@code hMax} the hue range wraps around red:
 * {@code {"hMin": 170, "hMax": 10}} takes hues 170..179 and 0..10.
 */
public record ColorRange(
        @Param(value = "Lowest hue (OpenCV scale, half degrees)", defaultValue = "145",
                min = 0, max = HUE_MAX)
        int hMin,
        @Param(value = "Highest hue; below hMin means the range wraps around 0", defaultValue = "175",
                min = 0, max = HUE_MAX)
        int hMax,
        @Param(value = "Lowest saturation", defaultValue = "90", min = 0, max = 255) int sMin,
        @Param(value = "Highest saturation", defaultValue = "255", min = 0, max = 255) int sMax,
        @Param(value = "Lowest value (brightness)", defaultValue = "60", min = 0, max = 255) int vMin,
        @Param(value = "Highest value (brightness)", defaultValue = "255", min = 0, max = 255) int vMax) {

    /** The largest hue OpenCV gives an 8-bit image. */
    public static final int HUE_MAX = 179;

    public ColorRange {
        if (sMin > sMax) {
            throw new IllegalArgumentException("sMin (" + sMin + ") must not be above sMax (" + sMax + ")");
        }
        if (vMin > vMax) {
            throw new IllegalArgumentException("vMin (" + vMin + ") must not be above vMax (" + vMax + ")");
        }
    }

    /** The pink of the target ball: hot pink and its shaded sides. */
    public static ColorRange pink() {
        return ParamsJson.defaults(ColorRange.class);
    }

    /** Whether the hue range wraps around red (hMin above hMax). */
    public boolean wraps() {
        return hMin > hMax;
    }

    /** Whether an HSV pixel falls in the class; the reference the OpenCV threshold must agree with. */
    public boolean contains(int h, int s, int v) {
        boolean hueIn = wraps() ? h >= hMin || h <= hMax : h >= hMin && h <= hMax;
        return hueIn && s >= sMin && s <= sMax && v >= vMin && v <= vMax;
    }
}
