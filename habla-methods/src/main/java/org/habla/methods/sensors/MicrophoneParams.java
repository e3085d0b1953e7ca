package org.habla.methods.sensors;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code microphone} method: its high-pass filter and its noise gate. */
public record MicrophoneParams(
        @Param(value = "Mix every channel down to one", defaultValue = "false")
        boolean downmix,
        @Param(value = "Corner of the first-order high-pass filter that removes DC and rumble", unit = "Hz",
                defaultValue = "80", min = 0, max = 2000)
        double highPassHz,
        @Param(value = "Apply the noise gate", defaultValue = "true")
        boolean gate,
        @Param(value = "How far above the noise floor a block must be to open the gate", unit = "dB",
                defaultValue = "6", min = 0, max = 60)
        double gateThresholdDb,
        @Param(value = "Gain of the closed gate (attenuation of noise)", unit = "dB", defaultValue = "-20",
                min = -120, max = 0)
        double closedGainDb,
        @Param(value = "Time constant with which the noise floor follows a rising level", unit = "ms",
                defaultValue = "3000", min = 10, max = 600_000)
        double floorRiseMs,
        @Param(value = "How long the gate stays open after the level falls", unit = "ms", defaultValue = "150",
                min = 0, max = 10_000)
        double holdMs,
        @Param(value = "Length of the blocks the gate measures", unit = "ms", defaultValue = "10", min = 1, max = 100)
        double blockMs,
        @Param(value = "Queue length of the audio input, in chunks", defaultValue = "64", min = 1, max = 4096)
        int queue) {

    /** Every parameter at its default. */
    public static MicrophoneParams defaults() {
        return ParamsJson.defaults(MicrophoneParams.class);
    }
}
