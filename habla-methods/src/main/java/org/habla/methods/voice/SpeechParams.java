package org.habla.methods.voice;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

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
        sampleRateHz = ParamRules.within(SpeechParams.class, "sampleRateHz", sampleRateHz, 4_000, 48_000);
        amplitude = ParamRules.within(SpeechParams.class, "amplitude", amplitude, 0, 1);
        wordGapMs = ParamRules.within(SpeechParams.class, "wordGapMs", wordGapMs, 0, 2000);
        chunkMs = ParamRules.within(SpeechParams.class, "chunkMs", chunkMs, 10, 2000);
        maxChars = ParamRules.within(SpeechParams.class, "maxChars", maxChars, 1, 10_000);
        speakEmotions = ParamDefaults.or(SpeechParams.class, "speakEmotions", speakEmotions);
        sayEmotions = java.util.List.copyOf(ParamDefaults.or(SpeechParams.class, "sayEmotions", sayEmotions));
        emotionIntervalMs = ParamRules.within(SpeechParams.class, "emotionIntervalMs", emotionIntervalMs, 0, 600_000);
    }

    /** Every parameter at its default. */
    public static SpeechParams defaults() {
        return new SpeechParams(null, null, null, null, null, null, null, null);
    }
}
