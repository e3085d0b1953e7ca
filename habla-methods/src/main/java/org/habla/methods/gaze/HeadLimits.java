package org.habla.methods.gaze;

import com.fasterxml.jackson.databind.JsonNode;
import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/**
 * The range of each head joint, in radians. Used as a params record by the methods that move a head,
 * and read from a head channel's metadata ({@code tiltMinRad}, {@code tiltMaxRad}, {@code panMinRad}, …).
 * Left out, a limit takes the value of a Sony ERS-7's head (tilt −1.31..0.05, pan ±1.62, nod −0.26..0.79).
 */
public record HeadLimits(
        @Param(value = "Lowest neck tilt (looking down)", unit = "rad", defaultValue = "-1.31") Double tiltMinRad,
        @Param(value = "Highest neck tilt", unit = "rad", defaultValue = "0.05") Double tiltMaxRad,
        @Param(value = "Pan furthest to the right", unit = "rad", defaultValue = "-1.62") Double panMinRad,
        @Param(value = "Pan furthest to the left", unit = "rad", defaultValue = "1.62") Double panMaxRad,
        @Param(value = "Lowest nod (looking down)", unit = "rad", defaultValue = "-0.26") Double nodMinRad,
        @Param(value = "Highest nod (looking up)", unit = "rad", defaultValue = "0.79") Double nodMaxRad) {

    public HeadLimits {
        tiltMinRad = ParamRules.within(HeadLimits.class, "tiltMinRad", tiltMinRad, -Math.PI, Math.PI);
        tiltMaxRad = ParamRules.within(HeadLimits.class, "tiltMaxRad", tiltMaxRad, -Math.PI, Math.PI);
        panMinRad = ParamRules.within(HeadLimits.class, "panMinRad", panMinRad, -Math.PI, Math.PI);
        panMaxRad = ParamRules.within(HeadLimits.class, "panMaxRad", panMaxRad, -Math.PI, Math.PI);
        nodMinRad = ParamRules.within(HeadLimits.class, "nodMinRad", nodMinRad, -Math.PI, Math.PI);
        nodMaxRad = ParamRules.within(HeadLimits.class, "nodMaxRad", nodMaxRad, -Math.PI, Math.PI);
        if (tiltMinRad > tiltMaxRad || panMinRad > panMaxRad || nodMinRad > nodMaxRad) {
            throw new IllegalArgumentException("each head joint's minimum must not exceed its maximum");
        }
    }

    /** The default (ERS-7) limits. */
    public static HeadLimits defaults() {
        return new HeadLimits(null, null, null, null, null, null);
    }

    /** The pose brought within the limits. */
    public HeadPose clamp(HeadPose p) {
        return new HeadPose(clamp(p.tiltRad(), tiltMinRad, tiltMaxRad), clamp(p.panRad(), panMinRad, panMaxRad),
                clamp(p.nodRad(), nodMinRad, nodMaxRad));
    }

    /**
     * These limits with every limit that {@code given} (a params record whose unset values are null)
     * leaves out taken from a channel's metadata, then from the defaults.
     */
    public static HeadLimits resolve(HeadLimitsOverride given, JsonNode metadata) {
        return new HeadLimits(
                pick(given.tiltMinRad(), metadata, "tiltMinRad"), pick(given.tiltMaxRad(), metadata, "tiltMaxRad"),
                pick(given.panMinRad(), metadata, "panMinRad"), pick(given.panMaxRad(), metadata, "panMaxRad"),
                pick(given.nodMinRad(), metadata, "nodMinRad"), pick(given.nodMaxRad(), metadata, "nodMaxRad"));
    }

    private static Double pick(Double given, JsonNode metadata, String field) {
        if (given != null) {
            return given;
        }
        JsonNode n = metadata == null ? null : metadata.get(field);
        return n != null && n.isNumber() && Double.isFinite(n.doubleValue()) ? n.doubleValue() : null;
    }

    private static double clamp(double v, double min, double max) {
        return Math.max(min, Math.min(max, v));
    }

    /** Limits as a config gives them: each one may be left out (null) to come from metadata or the defaults. */
    public interface HeadLimitsOverride {
        Double tiltMinRad();

        Double tiltMaxRad();

        Double panMinRad();

        Double panMaxRad();

        Double nodMinRad();

        Double nodMaxRad();
    }
}
