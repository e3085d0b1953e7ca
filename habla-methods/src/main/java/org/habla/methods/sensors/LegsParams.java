package org.habla.methods.sensors;

import com.fasterxml.jackson.databind.JsonNode;
import org.habla.config.ParamsJson;
import org.habla.methods.locomotion.WalkLimits;
import org.habla.plugin.Param;

/**
 * The params of the {@code legs} method: the walk limits commands are clamped to. Each one left out
 * comes from the metadata of the walk channel the output writes ({@code maxForwardMps}, …), else from
 * the defaults (a Sony ERS-7's walk as the {@code tekkotsu} driver states it).
 */
public record LegsParams(
        @Param(value = "Fastest forward walk", unit = "m/s", defaultNote = "channel metadata, else 0.18",
                min = 0, max = 10)
        Double maxForwardMps,
        @Param(value = "Fastest backward walk", unit = "m/s", defaultNote = "channel metadata, else 0.18",
                min = 0, max = 10)
        Double maxReverseMps,
        @Param(value = "Fastest sideways walk", unit = "m/s", defaultNote = "channel metadata, else 0.14",
                min = 0, max = 10)
        Double maxStrafeMps,
        @Param(value = "Fastest turn", unit = "rad/s", defaultNote = "channel metadata, else 1.8",
                min = 0, max = 20)
        Double maxRotateRadps,
        @Param(value = "Queue length of the walk input, in commands", defaultValue = "8",
                min = 1, max = 1024)
        int queue) {

    /** Every parameter at its default. */
    public static LegsParams defaults() {
        return ParamsJson.defaults(LegsParams.class);
    }

    /** The limits: each from these params, else from the walk channel's {@code metadata} (may be null), else the default. */
    public WalkLimits limits(JsonNode metadata) {
        return new WalkLimits(pick(maxForwardMps, metadata, "maxForwardMps", 0.18),
                pick(maxReverseMps, metadata, "maxReverseMps", 0.18),
                pick(maxStrafeMps, metadata, "maxStrafeMps", 0.14),
                pick(maxRotateRadps, metadata, "maxRotateRadps", 1.8));
    }

    private static double pick(Double given, JsonNode metadata, String field, double fallback) {
        if (given != null) {
            return given;
        }
        JsonNode n = metadata == null ? null : metadata.get(field);
        return n != null && n.isNumber() && n.doubleValue() >= 0 && Double.isFinite(n.doubleValue()) ? n.doubleValue() : fallback;
    }
}
