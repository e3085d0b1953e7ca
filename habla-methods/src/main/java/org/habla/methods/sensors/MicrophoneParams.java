package org.habla.methods.sensors;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/** The params of the {@code microphone} method: its high-pass filter and its noise gate. */
public record MicrophoneParams(
        @Param(value = "Mix every channel down to one", defaultValue = "false")
        Boolean downmix,
        @Param(value = "Corner of the first-order high-pass filter that removes DC and rumble", unit = "Hz",
                defaultValue = "80")
        Double highPassHz,
        @Param(value = "Apply the noise gate", defaultValue = "true")
        Boolean gate,
        @Param(value = "How far above the noise floor a block must be to open the gate", unit = "dB", defaultValue = "6")
        Double gateThresholdDb,
        @Param(value = "Gain of the closed gate (attenuation of noise)", unit = "dB", defaultValue = "-20")
        Double closedGainDb,
        @Param(value = "Time constant with which the noise floor follows a rising level", unit = "ms",
                defaultValue = "3000")
        Double floorRiseMs,
        @Param(value = "How long the gate stays open after the level falls", unit = "ms", defaultValue = "150")
        Double holdMs,
        @Param(value = "Length of the blocks the gate measures", unit = "ms", defaultValue = "10")
        Double blockMs,
        @Param(value = "Queue length of the audio input, in chunks", defaultValue = "64")
        Integer queue) {

    public MicrophoneParams {
        downmix = ParamDefaults.or(MicrophoneParams.class, "downmix", downmix);
        highPassHz = ParamRules.within(MicrophoneParams.class, "highPassHz", highPassHz, 0, 2000);
        gate = ParamDefaults.or(MicrophoneParams.class, "gate", gate);
        gateThresholdDb = ParamRules.within(MicrophoneParams.class, "gateThresholdDb", gateThresholdDb, 0, 60);
        closedGainDb = ParamRules.within(MicrophoneParams.class, "closedGainDb", closedGainDb, -120, 0);
        floorRiseMs = ParamRules.within(MicrophoneParams.class, "floorRiseMs", floorRiseMs, 10, 600_000);
        holdMs = ParamRules.within(MicrophoneParams.class, "holdMs", holdMs, 0, 10_000);
        blockMs = ParamRules.within(MicrophoneParams.class, "blockMs", blockMs, 1, 100);
        queue = ParamRules.within(MicrophoneParams.class, "queue", queue, 1, 4096);
    }

    /** Every parameter at its default. */
    public static MicrophoneParams defaults() {
        return new MicrophoneParams(null, null, null, null, null, null, null, null, null);
    }
}
