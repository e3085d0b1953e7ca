package org.habla.methods.gaze;

import com.fasterxml.jackson.databind.JsonNode;
import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/**
 * The range of each head joint, in radians. Used as a params record by the methods that move a head,
 * and read from a head channel's metadata ({@code tiltMinRad}, {@code tiltMaxRad}, {@code panMinRad}, …).
 * Left out, a limit takes the value of a Sony ERS-7's head (tilt −1.31..0.05, pan ±1.62, nod −0.26..0.79).
 */
public record HeadLimits(
        @Param(value = "Lowest neck tilt (looking down)", unit = "rad", defaultValue = "-1.31",
                min = -Math.PI, max = Math.PI)
        double tiltMinRad,
        @Param(value = "Highest neck tilt", unit = "rad", defaultValue = "0.05",
                min = -Math.PI, max = Math.PI)
        double tiltMaxRad,
        @Param(value = "Pan furthest to the right", unit = "rad", defaultValue = "-1.62",
                min = -Math.PI, max = Math.PI)
        double panMinRad,
        @Param(value = "Pan furthest to the left", unit = "rad", defaultValue = "1.62",
                min = -Math.PI, max = Math.PI)
        double panMaxRad,
        @Param(value = "Lowest nod (looking down)", unit = "rad", defaultValue = "-0.26",
                min = -Math.PI, max = Math.PI)
        double nodMinRad,
        @Param(value = "Highest nod (looking up)", unit = "rad", defaultValue = "0.79",
                min = -Math.PI, max = Math.PI)
        double nodMaxRad) {

    public HeadLimits {
        if (tiltMinRad > tiltMaxRad || panMinRad > panMaxRad || nodMinRad > nodMaxRad) {
            throw new IllegalArgumentException("each head joint's minimum must not exceed its maximum");
        }
    }

    private static final HeadLimits ERS7 = ParamsJson.defaults(HeadLimits.class);

    /** The default (ERS-7) limits. */
    public static HeadLimits defaults() {
        return ERS7;
    }

    /** The pose brought within the limits. */
    public HeadPose clamp(HeadPose p) {
        return new HeadPose(clamp(p.tiltRad(), tiltMinRad, tiltMaxRad), clamp(p.panRad(), panMinRad, panMaxRad),
                clamp(p.nodRad(), nodMinRad, nodMaxRad));
    }

    /**
     * The limits {@code given} (a params record whose unset values are null) says, every limit it leaves out
     * taken from a channel's metadata, then from the defaults.
     */
    public static HeadLimits resolve(HeadLimitsOverride given, JsonNode metadata) {
        return ofGiven(pick(given.tiltMinRad(), metadata, "tiltMinRad"), pick(given.tiltMaxRad(), metadata, "tiltMaxRad"),
                pick(given.panMinRad(), metadata, "panMinRad"), pick(given.panMaxRad(), metadata, "panMaxRad"),
                pick(given.nodMinRad(), metadata, "nodMinRad"), pick(given.nodMaxRad(), metadata, "nodMaxRad"));
    }

    /**
     * The limits given, each null one taken from the defaults.
     *
     * @throws IllegalArgumentException when a joint's minimum exceeds its maximum
     */
    public static HeadLimits ofGiven(Double tiltMinRad, Double tiltMaxRad, Double panMinRad, Double panMaxRad,
            Double nodMinRad, Double nodMaxRad) {
        HeadLimits d = ERS7;
        return new HeadLimits(or(tiltMinRad, d.tiltMinRad), or(tiltMaxRad, d.tiltMaxRad), or(panMinRad, d.panMinRad),
                or(panMaxRad, d.panMaxRad), or(nodMinRad, d.nodMinRad), or(nodMaxRad, d.nodMaxRad));
    }

    private static double or(Double given, double fallback) {
        return given == null ? fallback : given;
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
