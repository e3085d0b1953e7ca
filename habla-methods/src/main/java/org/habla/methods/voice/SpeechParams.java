package org.habla.methods.voice;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code speech} method: the sound of the voice and what it says on its own. */
public record SpeechParams(
        @Param(value = "Sample rate of the audio", unit = "Hz", defaultValue = "16000",
                min = 4_000, max = 48_000)
        int sampleRateHz,
        @Param(value = "Peak amplitude, as a share of full scale", defaultValue = "0.5",
                min = 0, max = 1)
        double amplitude,
        @Param(value = "Rest between words", unit = "ms", defaultValue = "60", min = 0, max = 2000) int wordGapMs,
        @Param(value = "Longest audio chunk emitted", unit = "ms", defaultValue = "500",
                min = 10, max = 2000)
        int chunkMs,
        @Param(value = "Longest text said; longer texts are cut", defaultValue = "200",
                min = 1, max = 10_000)
        int maxChars,
        @Param(value = "Say the emotion of each emotion record that changes it", defaultValue = "true")
        boolean speakEmotions,
        @Param(value = "The emotions said when an emotion record brings one of them",
                defaultValue = "[\"happy\",\"excited\",\"sad\",\"angry\"]")
        java.util.List<String> sayEmotions,
        @Param(value = "Least time between two emotions said", unit = "ms", defaultValue = "2000",
                min = 0, max = 600_000)
        int emotionIntervalMs) {

    public SpeechParams {
        sayEmotions = java.util.List.copyOf(sayEmotions);
    }

    /** Every parameter at its default. */
    public static SpeechParams defaults() {
        return ParamsJson.defaults(SpeechParams.class);
    }
}
