package org.habla.methods.speech;

import org.habla.methods.ParamRules;
import org.habla.methods.audio.AudioProcessingParams;
import org.habla.methods.audio.UtteranceGate;
import org.habla.plugin.Param;

/** The params of the {@code speech-recognition} method: the grammar, the backlog and its own endpointing. */
public record SpeechRecognitionParams(
        @Param(value = "Path of a JSGF grammar file (.gram) of the phrases to recognise; empty: the bundled "
                + "commands.gram (go forward, turn left, turn right, go back, stop, good dog, bad dog, well done, no)",
                defaultValue = "\"\"", file = true)
        String grammar,
        @Param(value = "Utterances kept waiting while one is decoded or the model loads; the oldest is dropped "
                + "beyond this", defaultValue = "4")
        Integer maxPending,
        @Param(value = "Voiced sound (pitch 70-500 Hz) an utterance must hold to be decoded; 0 decodes every "
                + "utterance", unit = "ms", defaultValue = "80")
        Double minVoicedMs,
        @Param(value = "Endpointing of the audio input: how far above the noise floor speech must be", unit = "dB",
                defaultValue = "12")
        Double openAboveFloorDb,
        @Param(value = "Endpointing of the audio input: the quietest level that can be speech", unit = "dBFS",
                defaultValue = "-50")
        Double minLevelDb,
        @Param(value = "Endpointing of the audio input: the pause that ends an utterance", unit = "ms",
                defaultValue = "300")
        Double hangoverMs,
        @Param(value = "Queue length of the audio and segments inputs, in chunks", defaultValue = "256")
        Integer queue) {

    public SpeechRecognitionParams {
        grammar = grammar == null ? "" : grammar.trim();
        if (!grammar.isEmpty() && !grammar.endsWith(".gram")) {
            throw new IllegalArgumentException("grammar must name a JSGF file ending in .gram, was '" + grammar + "'");
        }
        maxPending = ParamRules.within("maxPending", maxPending, 4, 1, 1000);
        minVoicedMs = ParamRules.within("minVoicedMs", minVoicedMs, 80, 0, 5000);
        openAboveFloorDb = ParamRules.within("openAboveFloorDb", openAboveFloorDb, 12, 0, 80);
        minLevelDb = ParamRules.within("minLevelDb", minLevelDb, -50, -120, 0);
        hangoverMs = ParamRules.within("hangoverMs", hangoverMs, 300, 0, 5000);
        queue = ParamRules.within("queue", queue, 256, 1, 65_536);
    }

    /** Every parameter at its default. */
    public static SpeechRecognitionParams defaults() {
        return new SpeechRecognitionParams(null, null, null, null, null, null, null);
    }

    /** The endpointing gate's settings: these params over the defaults of {@code audio-processing}. */
    UtteranceGate.Settings gate() {
        UtteranceGate.Settings d = AudioProcessingParams.defaults().gate();
        return new UtteranceGate.Settings(openAboveFloorDb, minLevelDb, hangoverMs, d.prerollMs(), d.minLoudMs(),
                d.maxSegmentMs(), d.floorRiseMs());
    }
}
