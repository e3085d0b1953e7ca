package org.habla.methods.vision;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/**
 * One colour class of {@code image-segmentation}: a box in OpenCV's HSV space (hue 0..179, saturation
 * and value 0..255). When {@code hMin} is greater than {@code hMax} the hue range wraps around red:
 * {@code {"hMin": 170, "hMax": 10}} takes hues 170..179 and 0..10.
 */
public record ColorRange(
        @Param(value = "Lowest hue (OpenCV scale, half degrees)", defaultValue = "145") Integer hMin,
        @Param(value = "Highest hue; below hMin means the range wraps around 0", defaultValue = "175") Integer hMax,
        @Param(value = "Lowest saturation", defaultValue = "90") Integer sMin,
        @Param(value = "Highest saturation", defaultValue = "255") Integer sMax,
        @Param(value = "Lowest value (brightness)", defaultValue = "60") Integer vMin,
        @Param(value = "Highest value (brightness)", defaultValue = "255") Integer vMax) {

    /** The largest hue OpenCV gives an 8-bit image. */
    public static final int HUE_MAX = 179;

    public ColorRange {
        hMin = ParamRules.within(ColorRange.class, "hMin", hMin, 0, HUE_MAX);
        hMax = ParamRules.within(ColorRange.class, "hMax", hMax, 0, HUE_MAX);
        sMin = ParamRules.within(ColorRange.class, "sMin", sMin, 0, 255);
        sMax = ParamRules.within(ColorRange.class, "sMax", sMax, 0, 255);
        vMin = ParamRules.within(ColorRange.class, "vMin", vMin, 0, 255);
        vMax = ParamRules.within(ColorRange.class, "vMax", vMax, 0, 255);
        if (sMin > sMax) {
            throw new IllegalArgumentException("sMin (" + sMin + ") must not be above sMax (" + sMax + ")");
        }
        if (vMin > vMax) {
            throw new IllegalArgumentException("vMin (" + vMin + ") must not be above vMax (" + vMax + ")");
        }
    }

    /** The pink of the target ball: hot pink and its shaded sides. */
    public static ColorRange pink() {
        return new ColorRange(null, null, null, null, null, null);
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
