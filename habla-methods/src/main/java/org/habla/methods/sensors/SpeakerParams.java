package org.habla.methods.sensors;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code speaker} method: volume, chunk size and the beeps made of text. */
public record SpeakerParams(
        @Param(value = "Gain applied to the sound; samples beyond full scale are clipped", unit = "dB", defaultValue = "0")
        Double volumeDb,
        @Param(value = "Longest chunk sent to the interface; longer sounds are split", unit = "ms", defaultValue = "500")
        Integer maxChunkMs,
        @Param(value = "Sample rate of the tones made from text", unit = "Hz", defaultValue = "16000") Integer sampleRateHz,
        @Param(value = "Peak amplitude of the tones made from text, as a share of full scale", defaultValue = "0.5")
        Double amplitude,
        @Param(value = "Queue length of the audio input, in chunks", defaultValue = "64") Integer queue) {

    public SpeakerParams {
        volumeDb = ParamRules.within(SpeakerParams.class, "volumeDb", volumeDb, -60, 30);
        maxChunkMs = ParamRules.within(SpeakerParams.class, "maxChunkMs", maxChunkMs, 10, 2000);
        sampleRateHz = ParamRules.within(SpeakerParams.class, "sampleRateHz", sampleRateHz, 4_000, 48_000);
        amplitude = ParamRules.within(SpeakerParams.class, "amplitude", amplitude, 0, 1);
        queue = ParamRules.within(SpeakerParams.class, "queue", queue, 1, 4096);
    }

    /** Every parameter at its default. */
    public static SpeakerParams defaults() {
        return new SpeakerParams(null, null, null, null, null);
    }
}
