package org.habla.methods.speech;

import java.nio.file.Path;
import java.util.Optional;
import org.habla.methods.ParamRules;
import org.habla.methods.audio.AudioProcessingParams;
import org.habla.methods.audio.UtteranceGate;
import org.habla.methods.audio.VoiceActivityDetector;
import org.habla.plugin.Param;

/** The params of the {@code speech-recognition} method: grammar, speaker, rejection, backlog and endpointing. */
public record SpeechRecognitionParams(
        @Param(value = "Path of a JSGF grammar file (.gram) of the phrases to recognise; empty: the bundled "
                + "commands.gram (go forward, turn left, turn right, go back, stop, good dog, bad dog, well done, no)",
                defaultValue = "\"\"", file = true)
        String grammar,
        @Param(value = "Path of a speaker's adaptation file written by 'habla enrol'; empty: the model as it comes",
                defaultValue = "\"\"", file = true)
        String adaptation,
        @Param(value = "The lowest confidence a phrase is said with; below it the utterance gives nothing",
                defaultValue = "0.1")
        Double minConfidence,
        @Param(value = "Prior of Sphinx's out-of-grammar branch (a loop of phones beside the grammar): the higher, "
                + "the more readily speech outside the grammar gives nothing; 0 (no branch) measured best",
                defaultValue = "0")
        Double outOfGrammarProbability,
        @Param(value = "Prior of each garbage word: near misses of the grammar's words from the pronouncing "
                + "dictionary, and its words alone, searched beside the phrases; when one wins, nothing is said. "
                + "0: no garbage words", defaultValue = "0.001")
        Double garbagePrior,
        @Param(value = "Noise removal in Sphinx's front end (spectral noise estimate subtracted per mel band)",
                defaultValue = "true")
        Boolean denoise,
        @Param(value = "Utterances kept waiting while one is decoded or the model loads; the oldest is dropped "
                + "beyond this", defaultValue = "4")
        Integer maxPending,
        @Param(value = "Voiced sound (pitch 70-500 Hz) an utterance must hold to be decoded; 0 decodes every "
                + "utterance", unit = "ms", defaultValue = "80")
        Double minVoicedMs,
        @Param(value = "Endpointing of the audio input: how far above the noise floor speech must be", unit = "dB",
                defaultValue = "10")
        Double openAboveFloorDb,
        @Param(value = "Endpointing of the audio input: the quietest speech", unit = "dBFS", defaultValue = "-55")
        Double minLevelDb,
        @Param(value = "Endpointing of the audio input: how long without speech ends an utterance", unit = "ms",
                defaultValue = "200")
        Double hangoverMs,
        @Param(value = "Early endpoint of the audio input: a phrase decoded while the hangover runs is said once the "
                + "pause is this long, unless speech resumed; at hangoverMs or above, only whole utterances are "
                + "decoded", unit = "ms", defaultValue = "100")
        Double endpointMs,
        @Param(value = "Early endpoint of the audio input only for utterances whose loudest part stands this far above "
                + "the noise floor: in more noise, pauses inside a phrase look like its end", unit = "dB",
                defaultValue = "30")
        Double endpointAboveFloorDb,
        @Param(value = "Queue length of the audio and segments inputs, in chunks", defaultValue = "256")
        Integer queue) {

    public SpeechRecognitionParams {
        grammar = ParamRules.or(SpeechRecognitionParams.class, "grammar", grammar).trim();
        if (!grammar.isEmpty() && !grammar.endsWith(".gram")) {
            throw new IllegalArgumentException("grammar must name a JSGF file ending in .gram, was '" + grammar + "'");
        }
        adaptation = ParamRules.or(SpeechRecognitionParams.class, "adaptation", adaptation).trim();
        minConfidence = ParamRules.within(SpeechRecognitionParams.class, "minConfidence", minConfidence, 0, 1);
        outOfGrammarProbability = ParamRules.within(SpeechRecognitionParams.class, "outOfGrammarProbability", outOfGrammarProbability, 0, 1);
        garbagePrior = ParamRules.within(SpeechRecognitionParams.class, "garbagePrior", garbagePrior, 0, 1);
        denoise = ParamRules.or(SpeechRecognitionParams.class, "denoise", denoise);
        maxPending = ParamRules.within(SpeechRecognitionParams.class, "maxPending", maxPending, 1, 1000);
        minVoicedMs = ParamRules.within(SpeechRecognitionParams.class, "minVoicedMs", minVoicedMs, 0, 5000);
        openAboveFloorDb = ParamRules.within(SpeechRecognitionParams.class, "openAboveFloorDb", openAboveFloorDb, 0, 80);
        minLevelDb = ParamRules.within(SpeechRecognitionParams.class, "minLevelDb", minLevelDb, -120, 0);
        hangoverMs = ParamRules.within(SpeechRecognitionParams.class, "hangoverMs", hangoverMs, 0, 5000);
        endpointMs = ParamRules.within(SpeechRecognitionParams.class, "endpointMs", endpointMs, 0, 5000);
        endpointAboveFloorDb = ParamRules.within(SpeechRecognitionParams.class, "endpointAboveFloorDb", endpointAboveFloorDb, 0, 200);
        queue = ParamRules.within(SpeechRecognitionParams.class, "queue", queue, 1, 65_536);
    }

    /** Every parameter at its default. */
    public static SpeechRecognitionParams defaults() {
        return new SpeechRecognitionParams(null, null, null, null, null, null, null, null, null, null, null, null, null, null);
    }

    /** These params with another grammar file. */
    public SpeechRecognitionParams withGrammar(String file) {
        return new SpeechRecognitionParams(file, adaptation, minConfidence, outOfGrammarProbability, garbagePrior, denoise,
                maxPending, minVoicedMs, openAboveFloorDb, minLevelDb, hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** These params with a speaker's adaptation file. */
    public SpeechRecognitionParams withAdaptation(String file) {
        return new SpeechRecognitionParams(grammar, file, minConfidence, outOfGrammarProbability, garbagePrior, denoise,
                maxPending, minVoicedMs, openAboveFloorDb, minLevelDb, hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** These params with another confidence threshold. */
    public SpeechRecognitionParams withMinConfidence(double threshold) {
        return new SpeechRecognitionParams(grammar, adaptation, threshold, outOfGrammarProbability, garbagePrior, denoise,
                maxPending, minVoicedMs, openAboveFloorDb, minLevelDb, hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** These params with another backlog. */
    public SpeechRecognitionParams withMaxPending(int n) {
        return new SpeechRecognitionParams(grammar, adaptation, minConfidence, outOfGrammarProbability, garbagePrior, denoise, n,
                minVoicedMs, openAboveFloorDb, minLevelDb, hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** These params with another early endpoint (at hangoverMs or above: none). */
    public SpeechRecognitionParams withEndpointMs(double ms) {
        return new SpeechRecognitionParams(grammar, adaptation, minConfidence, outOfGrammarProbability, garbagePrior, denoise,
                maxPending, minVoicedMs, openAboveFloorDb, minLevelDb, hangoverMs, ms, endpointAboveFloorDb, queue);
    }

    /** The adaptation file, if one is named. */
    Optional<Path> adaptationFile() {
        return adaptation.isEmpty() ? Optional.empty() : Optional.of(Path.of(adaptation));
    }

    /** The endpointing gate's settings: these params over the defaults of {@code audio-processing}. */
    UtteranceGate.Settings gate() {
        UtteranceGate.Settings d = AudioProcessingParams.defaults().gate();
        VoiceActivityDetector.Settings v = d.detector();
        return new UtteranceGate.Settings(
                new VoiceActivityDetector.Settings(openAboveFloorDb, v.openAboveBackgroundDb(), minLevelDb,
                        v.noiseWindowMs()),
                d.closeBelowOpenDb(), d.peakRangeDb(), hangoverMs, d.prerollMs(), d.minLoudMs(), d.maxSegmentMs());
    }
}
