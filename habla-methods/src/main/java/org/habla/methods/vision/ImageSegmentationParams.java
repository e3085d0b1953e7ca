package org.habla.methods.vision;

import java.util.LinkedHashMap;
import java.util.Map;
import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/**
 * The params of the {@code image-segmentation} method: the colour classes to find and how blobs are
 * cleaned and kept.
 */
public record ImageSegmentationParams(
        @Param(value = "Colour classes by label, each an HSV box; the first one feeds output largest",
                defaultValue = "{\"pink\": {\"hMin\": 145, \"hMax\": 175, \"sMin\": 90, \"vMin\": 60}}")
        Map<String, ColorRange> colors,
        @Param(value = "Smallest blob kept", unit = "px", defaultValue = "12", min = 1, max = 1 << 28)
        int minAreaPx,
        @Param(value = "Side of the square opening (erode then dilate) that removes specks; 0 or 1 skips it",
                unit = "px", defaultValue = "5", min = 0, max = 31)
        int openPx,
        @Param(value = "Side of the square closing (dilate then erode) that fills holes; 0 or 1 skips it",
                unit = "px", defaultValue = "3", min = 0, max = 31)
        int closePx,
        @Param(value = "Most blobs reported per frame, largest first", defaultValue = "16", min = 1, max = 1024)
        int maxBlobs) {

    /** The most colour classes a method may look for. */
    public static final int MAX_COLORS = 16;

    public ImageSegmentationParams {
        if (colors.isEmpty() || colors.size() > MAX_COLORS) {
            throw new IllegalArgumentException("colors must name 1.." + MAX_COLORS + " classes, has " + colors.size());
        }
        for (Map.Entry<String, ColorRange> c : colors.entrySet()) {
            if (c.getKey().isBlank() || c.getValue() == null) {
                throw new IllegalArgumentException("colors needs a non-blank label and a range for each class, got '"
                        + c.getKey() + "'");
            }
        }
        colors = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(colors));
    }

    /** Every parameter at its default: one class, pink. */
    public static ImageSegmentationParams defaults() {
        return ParamsJson.defaults(ImageSegmentationParams.class);
    }

    /** The label of the first class, the one output {@code largest} follows. */
    public String firstLabel() {
        return colors.keySet().iterator().next();
    }
}
