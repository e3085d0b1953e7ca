package org.habla.methods.voice;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code speech} method: the sound of the voice and what it says on its own. */
public record SpeechParams(
        @Param(value = "Sample rate of the audio", unit = "Hz", defaultValue = "16000") Integer sampleRateHz,
        @Param(value = "Peak amplitude, as a share of full scale", defaultValue = "0.5") Double amplitude,
        @Param(value = "Rest between words", unit = "ms", defaultValue = "60") Integer wordGapMs,
        @Param(value = "Longest audio chunk emitted", unit = "ms", defaultValue = "500") Integer chunkMs,
        @Param(value = "Longest text said; longer texts are cut", defaultValue = "200") Integer maxChars,
        @Param(value = "Say the emotion of each emotion record that changes it", defaultValue = "true")
        Boolean speakEmotions,
        @Param(value = "The emotions said when an emotion record brings one of them",
                defaultValue = "[\"happy\",\"excited\",\"sad\",\"angry\"]")
        java.util.List<String> sayEmotions,
        @Param(value = "Least time between two emotions said", unit = "ms", defaultValue = "2000")
        Integer emotionIntervalMs) {

    public SpeechParams {
        sampleRateHz = ParamRules.within("sampleRateHz", sampleRateHz, 16_000, 4_000, 48_000);
        amplitude = ParamRules.within("amplitude", amplitude, 0.5, 0, 1);
        wordGapMs = ParamRules.within("wordGapMs", wordGapMs, 60, 0, 2000);
        chunkMs = ParamRules.within("chunkMs", chunkMs, 500, 10, 2000);
        maxChars = ParamRules.within("maxChars", maxChars, 200, 1, 10_000);
        speakEmotions = speakEmotions == null ? Boolean.TRUE : speakEmotions;
        sayEmotions = sayEmotions == null ? java.util.List.of("happy", "excited", "sad", "angry")
                : java.util.List.copyOf(sayEmotions);
        emotionIntervalMs = ParamRules.within("emotionIntervalMs", emotionIntervalMs, 2000, 0, 600_000);
    }

    /** Every parameter at its default. */
    public static SpeechParams defaults() {
        return new SpeechParams(null, null, null, null, null, null, null, null);
    }
}
