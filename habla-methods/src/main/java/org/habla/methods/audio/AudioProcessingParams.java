package org.habla.methods.audio;

import org.habla.config.ParamsJson;
import org.habla.plugin.Param;

/** The params of the {@code audio-processing} method: its frames, its pitch range and its utterance gate. */
public record AudioProcessingParams(
        @Param(value = "Length of one analysis frame (one features record each)", unit = "ms", defaultValue = "32",
                min = 4, max = 200)
        double frameMs,
        @Param(value = "Number of equal-width spectrum bands from 0 Hz to half the sample rate", defaultValue = "16",
                min = 1, max = 256)
        int bands,
        @Param(value = "Lowest pitch looked for (the frame must hold two periods of it)", unit = "Hz",
                defaultValue = "70", min = 20, max = 4000)
        double minPitchHz,
        @Param(value = "Highest pitch looked for", unit = "Hz", defaultValue = "1200", min = 40, max = 8000)
        double maxPitchHz,
        @Param(value = "Largest YIN normalised difference still called periodic", defaultValue = "0.15",
                min = 0.01, max = 1)
        double aperiodicity,
        @Param(value = "Quietest frame that can be voiced", unit = "dBFS", defaultValue = "-50", min = -120, max = 0)
        double voicedMinDb,
        @Param(value = "Voice activity: how far above the noise floor (the quietest tenth of the last noiseWindowMs) "
                + "the speech band must be", unit = "dB", defaultValue = "10", min = 0, max = 80)
        double openAboveFloorDb,
        @Param(value = "Voice activity: how far above the background (the median level of the last noiseWindowMs: "
                + "steady noise, distant talk) the speech band must be", unit = "dB", defaultValue = "9",
                min = 0, max = 80)
        double openAboveBackgroundDb,
        @Param(value = "Voice activity: the quietest speech, whatever the room", unit = "dBFS", defaultValue = "-55",
                min = -120, max = 0)
        double minLevelDb,
        @Param(value = "Voice activity: the stretch of stream the floor and background are measured over", unit = "ms",
                defaultValue = "3000", min = 100, max = 60_000)
        double noiseWindowMs,
        @Param(value = "Once open, how far below the opening level a frame may fall and still count as speech",
                unit = "dB", defaultValue = "1", min = 0, max = 40)
        double closeBelowOpenDb,
        @Param(value = "Once open, how far below the utterance's loudest frame a frame may fall and still count as "
                + "speech (an echo dying away does not)", unit = "dB", defaultValue = "30", min = 6, max = 120)
        double peakRangeDb,
        @Param(value = "How long without speech ends a segment", unit = "ms", defaultValue = "200", min = 0, max = 5000)
        double hangoverMs,
        @Param(value = "Audio kept from before the first speech frame", unit = "ms", defaultValue = "200",
                min = 0, max = 2000)
        double prerollMs,
        @Param(value = "Shortest speech a segment must hold (shorter ones are clicks)", unit = "ms",
                defaultValue = "80", min = 0, max = 10_000)
        double minLoudMs,
        @Param(value = "Longest segment; a longer stretch is cut here", unit = "ms", defaultValue = "8000",
                min = 100, max = 60_000)
        double maxSegmentMs,
        @Param(value = "Queue length of the audio input, in chunks", defaultValue = "256", min = 1, max = 65_536)
        int queue) {

    public AudioProcessingParams {
        if (!(maxPitchHz > minPitchHz)) {
            throw new IllegalArgumentException("maxPitchHz (" + maxPitchHz + ") must be above minPitchHz ("
                    + minPitchHz + ")");
        }
    }

    /** Every parameter at its default. */
    public static AudioProcessingParams defaults() {
        return ParamsJson.defaults(AudioProcessingParams.class);
    }

    /** The utterance gate's part of the params. */
    public UtteranceGate.Settings gate() {
        return new UtteranceGate.Settings(
                new VoiceActivityDetector.Settings(openAboveFloorDb, openAboveBackgroundDb, minLevelDb, noiseWindowMs),
                closeBelowOpenDb, peakRangeDb, hangoverMs, prerollMs, minLoudMs, maxSegmentMs);
    }
}
