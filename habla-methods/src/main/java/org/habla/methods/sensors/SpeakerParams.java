package org.habla.methods.sensors;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code speaker} method: volume, chunk size and the beeps made of text. */
public record SpeakerParams(
        @Param(value = "Gain applied to the sound; samples beyond full scale are clipped", unit = "dB",
                defaultValue = "0", min = -60, max = 30)
        double volumeDb,
        @Param(value = "Longest chunk sent to the interface; longer sounds are split", unit = "ms",
                defaultValue = "500", min = 10, max = 2000)
        int maxChunkMs,
        @Param(value = "Sample rate of the tones made from text", unit = "Hz", defaultValue = "16000",
                min = 4_000, max = 48_000)
        int sampleRateHz,
        @Param(value = "Peak amplitude of the tones made from text, as a share of full scale", defaultValue = "0.5",
                min = 0, max = 1)
        double amplitude,
        @Param(value = "Queue length of the audio input, in chunks", defaultValue = "64",
                min = 1, max = 4096)
        int queue) {

    /** Every parameter at its default. */
    public static SpeakerParams defaults() {
        return ParamsJson.defaults(SpeakerParams.class);
    }
}
