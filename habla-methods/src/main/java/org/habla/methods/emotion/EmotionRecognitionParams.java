package org.habla.methods.emotion;

import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code emotion-recognition} method: the word lists, the touch meanings and the rule thresholds. */
public record EmotionRecognitionParams(
        @Param(value = "Valence in [-1, 1] of words and phrases; longer phrases match first",
                defaultValue = "{\"good dog\":1,\"well done\":1,\"good\":0.8,\"great\":0.8,\"yes\":0.5,"
                        + "\"bad dog\":-1,\"bad\":-0.8,\"no\":-0.7,\"stop\":-0.3}")
        Map<String, Double> valence,
        @Param(value = "Valence in [-1, 1] of a touch event, by button name",
                defaultValue = "{\"backMiddle\":1,\"backFront\":0.6,\"backRear\":0.6,\"chin\":0.5,\"headTouch\":-1}")
        Map<String, Double> touchValence,
        @Param(value = "How long before the words the voice's frames count for them", unit = "ms",
                defaultValue = "3000", min = 100, max = 60_000)
        int utteranceWindowMs,
        @Param(value = "Share of each utterance's level and pitch that moves the running baseline",
                defaultValue = "0.2", min = 0, max = 1)
        double baselineWeight,
        @Param(value = "How many speakers get a baseline of their own, told apart by pitch", defaultValue = "1",
                min = 1, max = 8)
        int voices,
        @Param(value = "An utterance this far in pitch from every baseline starts a new one (while fewer than voices)",
                unit = "octaves", defaultValue = "0.35", min = 0.05, max = 4)
        double voiceSplitOctaves,
        @Param(value = "Level above the baseline that counts as fully loud", unit = "dB", defaultValue = "12",
                min = 0.1, max = 100)
        double loudRangeDb,
        @Param(value = "Pitch rise above the baseline that counts as fully high", unit = "octaves",
                defaultValue = "0.5", min = 0.01, max = 4)
        double pitchRangeOctaves,
        @Param(value = "Valence from which the emotion is positive (happy or excited)", defaultValue = "0.3",
                min = 0, max = 1)
        double positiveValence,
        @Param(value = "Arousal from which a positive emotion is excited", defaultValue = "0.7",
                min = 0, max = 1)
        double excitedArousal,
        @Param(value = "Arousal from which a negative emotion is angry rather than sad", defaultValue = "0.5",
                min = 0, max = 1)
        double angryArousal) {

    public EmotionRecognitionParams {
        valence = lowerCased(valence, "valence");
        touchValence = checked(touchValence,
                "touchValence");
    }

    /** Every parameter at its default. */
    public static EmotionRecognitionParams defaults() {
        return ParamsJson.defaults(EmotionRecognitionParams.class);
    }

    private static Map<String, Double> lowerCased(Map<String, Double> in, String name) {
        Map<String, Double> out = new TreeMap<>();
        checked(in, name).forEach((k, v) -> out.put(k.trim().toLowerCase(Locale.ROOT).replaceAll("\\s+", " "), v));
        return Map.copyOf(out);
    }

    private static Map<String, Double> checked(Map<String, Double> in, String name) {
        for (Map.Entry<String, Double> e : in.entrySet()) {
            if (e.getKey().isBlank() || e.getValue() == null || !(e.getValue() >= -1 && e.getValue() <= 1)) {
                throw new IllegalArgumentException(name + " entry '" + e.getKey() + "' needs a value within [-1, 1], was "
                        + e.getValue());
            }
        }
        return Map.copyOf(in);
    }
}
