package org.habla.methods.audio;

import org.habla.methods.ParamRules;
import org.habla.plugin.Param;

/** The params of the {@code audio-processing} method: its frames, its pitch range and its utterance gate. */
public record AudioProcessingParams(
        @Param(value = "Length of one analysis frame (one features record each)", unit = "ms", defaultValue = "32")
        Double frameMs,
        @Param(value = "Number of equal-width spectrum bands from 0 Hz to half the sample rate", defaultValue = "16")
        Integer bands,
        @Param(value = "Lowest pitch looked for (the frame must hold two periods of it)", unit = "Hz",
                defaultValue = "70")
        Double minPitchHz,
        @Param(value = "Highest pitch looked for", unit = "Hz", defaultValue = "1200")
        Double maxPitchHz,
        @Param(value = "Largest YIN normalised difference still called periodic", defaultValue = "0.15")
        Double aperiodicity,
        @Param(value = "Quietest frame that can be voiced", unit = "dBFS", defaultValue = "-50")
        Double voicedMinDb,
        @Param(value = "How far above the noise floor a frame must be to open the utterance gate", unit = "dB",
                defaultValue = "12")
        Double openAboveFloorDb,
        @Param(value = "Quietest frame that can open the gate, whatever the floor", unit = "dBFS", defaultValue = "-50")
        Double minLevelDb,
        @Param(value = "How long the level must stay below the gate before a segment ends", unit = "ms",
                defaultValue = "300")
        Double hangoverMs,
        @Param(value = "Audio kept from before the gate opened", unit = "ms", defaultValue = "150")
        Double prerollMs,
        @Param(value = "Shortest loud stretch a segment must have (shorter ones are clicks)", unit = "ms",
                defaultValue = "100")
        Double minLoudMs,
        @Param(value = "Longest segment; a longer stretch is cut here", unit = "ms", defaultValue = "8000")
        Double maxSegmentMs,
        @Param(value = "Time constant with which the noise floor follows a rising level", unit = "ms",
                defaultValue = "10000")
        Double floorRiseMs,
        @Param(value = "Queue length of the audio input, in chunks", defaultValue = "256")
        Integer queue) {

    public AudioProcessingParams {
        frameMs = ParamRules.within("frameMs", frameMs, 32, 4, 200);
        bands = ParamRules.within("bands", bands, 16, 1, 256);
        minPitchHz = ParamRules.within("minPitchHz", minPitchHz, 70, 20, 4000);
        maxPitchHz = ParamRules.within("maxPitchHz", maxPitchHz, 1200, 40, 8000);
        if (!(maxPitchHz > minPitchHz)) {
            throw new IllegalArgumentException("maxPitchHz (" + maxPitchHz + ") must be above minPitchHz ("
                    + minPitchHz + ")");
        }
        aperiodicity = ParamRules.within("aperiodicity", aperiodicity, 0.15, 0.01, 1);
        voicedMinDb = ParamRules.within("voicedMinDb", voicedMinDb, -50, -120, 0);
        openAboveFloorDb = ParamRules.within("openAboveFloorDb", openAboveFloorDb, 12, 0, 80);
        minLevelDb = ParamRules.within("minLevelDb", minLevelDb, -50, -120, 0);
        hangoverMs = ParamRules.within("hangoverMs", hangoverMs, 300, 0, 5000);
        prerollMs = ParamRules.within("prerollMs", prerollMs, 150, 0, 2000);
        minLoudMs = ParamRules.within("minLoudMs", minLoudMs, 100, 0, 10_000);
        maxSegmentMs = ParamRules.within("maxSegmentMs", maxSegmentMs, 8000, 100, 60_000);
        floorRiseMs = ParamRules.within("floorRiseMs", floorRiseMs, 10_000, 10, 600_000);
        queue = ParamRules.within("queue", queue, 256, 1, 65_536);
    }

    /** Every parameter at its default. */
    public static AudioProcessingParams defaults() {
        return new AudioProcessingParams(null, null, null, null, null, null, null, null, null, null, null, null,
                null, null);
    }

    /** The utterance gate's part of the params. */
    public UtteranceGate.Settings gate() {
        return new UtteranceGate.Settings(openAboveFloorDb, minLevelDb, hangoverMs, prerollMs, minLoudMs,
                maxSegmentMs, floorRiseMs);
    }
}
