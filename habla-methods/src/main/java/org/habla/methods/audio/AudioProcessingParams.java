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
        @Param(value = "Voice activity: how far above the noise floor (the quietest tenth of the last noiseWindowMs) "
                + "the speech band must be", unit = "dB", defaultValue = "10")
        Double openAboveFloorDb,
        @Param(value = "Voice activity: how far above the background (the median level of the last noiseWindowMs: "
                + "steady noise, distant talk) the speech band must be", unit = "dB", defaultValue = "9")
        Double openAboveBackgroundDb,
        @Param(value = "Voice activity: the quietest speech, whatever the room", unit = "dBFS", defaultValue = "-55")
        Double minLevelDb,
        @Param(value = "Voice activity: the stretch of stream the floor and background are measured over", unit = "ms",
                defaultValue = "3000")
        Double noiseWindowMs,
        @Param(value = "Once open, how far below the opening level a frame may fall and still count as speech",
                unit = "dB", defaultValue = "1")
        Double closeBelowOpenDb,
        @Param(value = "Once open, how far below the utterance's loudest frame a frame may fall and still count as "
                + "speech (an echo dying away does not)", unit = "dB", defaultValue = "30")
        Double peakRangeDb,
        @Param(value = "How long without speech ends a segment", unit = "ms", defaultValue = "200")
        Double hangoverMs,
        @Param(value = "Audio kept from before the first speech frame", unit = "ms", defaultValue = "200")
        Double prerollMs,
        @Param(value = "Shortest speech a segment must hold (shorter ones are clicks)", unit = "ms", defaultValue = "80")
        Double minLoudMs,
        @Param(value = "Longest segment; a longer stretch is cut here", unit = "ms", defaultValue = "8000")
        Double maxSegmentMs,
        @Param(value = "Queue length of the audio input, in chunks", defaultValue = "256")
        Integer queue) {

    public AudioProcessingParams {
        frameMs = ParamRules.within(AudioProcessingParams.class, "frameMs", frameMs, 4, 200);
        bands = ParamRules.within(AudioProcessingParams.class, "bands", bands, 1, 256);
        minPitchHz = ParamRules.within(AudioProcessingParams.class, "minPitchHz", minPitchHz, 20, 4000);
        maxPitchHz = ParamRules.within(AudioProcessingParams.class, "maxPitchHz", maxPitchHz, 40, 8000);
        if (!(maxPitchHz > minPitchHz)) {
            throw new IllegalArgumentException("maxPitchHz (" + maxPitchHz + ") must be above minPitchHz ("
                    + minPitchHz + ")");
        }
        aperiodicity = ParamRules.within(AudioProcessingParams.class, "aperiodicity", aperiodicity, 0.01, 1);
        voicedMinDb = ParamRules.within(AudioProcessingParams.class, "voicedMinDb", voicedMinDb, -120, 0);
        openAboveFloorDb = ParamRules.within(AudioProcessingParams.class, "openAboveFloorDb", openAboveFloorDb, 0, 80);
        openAboveBackgroundDb = ParamRules.within(AudioProcessingParams.class, "openAboveBackgroundDb", openAboveBackgroundDb, 0, 80);
        minLevelDb = ParamRules.within(AudioProcessingParams.class, "minLevelDb", minLevelDb, -120, 0);
        noiseWindowMs = ParamRules.within(AudioProcessingParams.class, "noiseWindowMs", noiseWindowMs, 100, 60_000);
        closeBelowOpenDb = ParamRules.within(AudioProcessingParams.class, "closeBelowOpenDb", closeBelowOpenDb, 0, 40);
        peakRangeDb = ParamRules.within(AudioProcessingParams.class, "peakRangeDb", peakRangeDb, 6, 120);
        hangoverMs = ParamRules.within(AudioProcessingParams.class, "hangoverMs", hangoverMs, 0, 5000);
        prerollMs = ParamRules.within(AudioProcessingParams.class, "prerollMs", prerollMs, 0, 2000);
        minLoudMs = ParamRules.within(AudioProcessingParams.class, "minLoudMs", minLoudMs, 0, 10_000);
        maxSegmentMs = ParamRules.within(AudioProcessingParams.class, "maxSegmentMs", maxSegmentMs, 100, 60_000);
        queue = ParamRules.within(AudioProcessingParams.class, "queue", queue, 1, 65_536);
    }

    /** Every parameter at its default. */
    public static AudioProcessingParams defaults() {
        return new AudioProcessingParams(null, null, null, null, null, null, null, null, null, null, null, null,
                null, null, null, null, null);
    }

    /** The utterance gate's part of the params. */
    public UtteranceGate.Settings gate() {
        return new UtteranceGate.Settings(
                new VoiceActivityDetector.Settings(openAboveFloorDb, openAboveBackgroundDb, minLevelDb, noiseWindowMs),
                closeBelowOpenDb, peakRangeDb, hangoverMs, prerollMs, minLoudMs, maxSegmentMs);
    }
}
