package org.habla.methods.speech;

import java.nio.file.Path;
import java.util.Optional;
import org.habla.config.ParamsJson;
import org.habla.methods.audio.AudioProcessingParams;
import org.habla.methods.audio.UtteranceGate;
import org.habla.methods.audio.VoiceActivityDetector;
import org.habla.plugin.Param;

/** The params of the {@code speech-recognition} method: grammar, speaker, rejection, backlog and endpointing. */
public record SpeechRecognitionParams(
        @Param(value = "The recogniser: sphinx4 (Sphinx-4's US English model, in the JAR) or moonshine (Moonshine base-en "
                + "on ONNX Runtime, fetched by ./habla models fetch); both are held to the grammar",
                defaultValue = "\"sphinx4\"")
        String engine,
        @Param(value = "Folder of the Moonshine model; empty: the cache folder ./habla models fetch fills "
                + "($HABLA_MODELS/moonshine-base-en, default ~/.cache/habla/models/moonshine-base-en)",
                defaultValue = "\"\"")
        String model,
        @Param(value = "Moonshine: the lowest confidence a phrase is said with (e^-mean shortfall of its tokens from "
                + "the model's own choice at each step); below it the utterance gives nothing; 0.15 silenced 90 % of "
                + "speech outside the grammar on the tune voices", defaultValue = "0.15", min = 0, max = 1)
        double moonshineMinConfidence,
        @Param(value = "Moonshine: log-probability added per step (token or end) of a phrase when choosing the best "
                + "one, so that a one-word phrase needs clearer evidence than a longer one; 8 measured best on the tune "
                + "voices", defaultValue = "8", min = 0, max = 50)
        double moonshineStepBonus,
        @Param(value = "Moonshine: threads ONNX Runtime uses for one utterance", defaultValue = "1", min = 1, max = 16)
        int threads,
        @Param(value = "Path of a JSGF grammar file (.gram) of the phrases to recognise; empty: the bundled "
                + "commands.gram (go forward, turn left, turn right, go back, stop, good dog, bad dog, well done, no)",
                defaultValue = "\"\"", file = true)
        String grammar,
        @Param(value = "Path of a speaker's adaptation file written by 'habla enrol'; empty: the model as it comes",
                defaultValue = "\"\"", file = true)
        String adaptation,
        @Param(value = "The lowest confidence a phrase is said with; below it the utterance gives nothing",
                defaultValue = "0.1", min = 0, max = 1)
        double minConfidence,
        @Param(value = "Prior of Sphinx's out-of-grammar branch (a loop of phones beside the grammar): the higher, "
                + "the more readily speech outside the grammar gives nothing; 0 (no branch) measured best",
                defaultValue = "0", min = 0, max = 1)
        double outOfGrammarProbability,
        @Param(value = "Prior of each garbage word: near misses of the grammar's words from the pronouncing "
                + "dictionary, and its words alone, searched beside the phrases; when one wins, nothing is said. "
                + "0: no garbage words", defaultValue = "0.001", min = 0, max = 1)
        double garbagePrior,
        @Param(value = "Noise removal in Sphinx's front end (spectral noise estimate subtracted per mel band)",
                defaultValue = "true")
        boolean denoise,
        @Param(value = "Utterances kept waiting while one is decoded or the model loads; the oldest is dropped "
                + "beyond this", defaultValue = "4", min = 1, max = 1000)
        int maxPending,
        @Param(value = "Voiced sound (pitch 70-500 Hz) an utterance must hold to be decoded; 0 decodes every "
                + "utterance", unit = "ms", defaultValue = "80", min = 0, max = 5000)
        double minVoicedMs,
        @Param(value = "Endpointing of the audio input: how far above the noise floor speech must be", unit = "dB",
                defaultValue = "10", min = 0, max = 80)
        double openAboveFloorDb,
        @Param(value = "Endpointing of the audio input: the quietest speech", unit = "dBFS", defaultValue = "-55",
                min = -120, max = 0)
        double minLevelDb,
        @Param(value = "Endpointing of the audio input: how long without speech ends an utterance", unit = "ms",
                defaultValue = "200", min = 0, max = 5000)
        double hangoverMs,
        @Param(value = "Early endpoint of the audio input: a phrase decoded while the hangover runs is said once the "
                + "pause is this long, unless speech resumed; at hangoverMs or above, only whole utterances are "
                + "decoded", unit = "ms", defaultValue = "100", min = 0, max = 5000)
        double endpointMs,
        @Param(value = "Early endpoint of the audio input only for utterances whose loudest part stands this far above "
                + "the noise floor: in more noise, pauses inside a phrase look like its end", unit = "dB",
                defaultValue = "30", min = 0, max = 200)
        double endpointAboveFloorDb,
        @Param(value = "Queue length of the audio and segments inputs, in chunks", defaultValue = "256",
                min = 1, max = 65_536)
        int queue) {

    /** The engines a config may name. */
    static final java.util.List<String> ENGINES = java.util.List.of("sphinx4", "moonshine");

    public SpeechRecognitionParams {
        engine = engine.trim();
        if (!ENGINES.contains(engine)) {
            throw new IllegalArgumentException("engine must be one of " + ENGINES + ", was '" + engine + "'");
        }
        model = model.trim();
        if (engine.equals("moonshine") && !MoonshineFiles.missing(modelFolder(model)).isEmpty()) {
            throw new IllegalArgumentException(MoonshineFiles.missing(modelFolder(model)));
        }
        grammar = grammar.trim();
        if (!grammar.isEmpty() && !grammar.endsWith(".gram")) {
            throw new IllegalArgumentException("grammar must name a JSGF file ending in .gram, was '" + grammar + "'");
        }
        adaptation = adaptation.trim();
    }

    /** Every parameter at its default. */
    public static SpeechRecognitionParams defaults() {
        return ParamsJson.defaults(SpeechRecognitionParams.class);
    }

    /** These params with another grammar file. */
    public SpeechRecognitionParams withGrammar(String file) {
        return new SpeechRecognitionParams(engine, model, moonshineMinConfidence, moonshineStepBonus,
                threads, file, adaptation,
                minConfidence, outOfGrammarProbability, garbagePrior, denoise,
                maxPending, minVoicedMs, openAboveFloorDb, minLevelDb, hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** These params with a speaker's adaptation file. */
    public SpeechRecognitionParams withAdaptation(String file) {
        return new SpeechRecognitionParams(engine, model, moonshineMinConfidence, moonshineStepBonus,
                threads, grammar, file,
                minConfidence, outOfGrammarProbability, garbagePrior, denoise,
                maxPending, minVoicedMs, openAboveFloorDb, minLevelDb, hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** These params with another confidence threshold. */
    public SpeechRecognitionParams withMinConfidence(double threshold) {
        return new SpeechRecognitionParams(engine, model, moonshineMinConfidence, moonshineStepBonus,
                threads, grammar, adaptation,
                threshold, outOfGrammarProbability, garbagePrior, denoise,
                maxPending, minVoicedMs, openAboveFloorDb, minLevelDb, hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** These params with another backlog. */
    public SpeechRecognitionParams withMaxPending(int n) {
        return new SpeechRecognitionParams(engine, model, moonshineMinConfidence, moonshineStepBonus,
                threads, grammar, adaptation,
                minConfidence, outOfGrammarProbability, garbagePrior, denoise, n,
                minVoicedMs, openAboveFloorDb, minLevelDb, hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** These params with another early endpoint (at hangoverMs or above: none). */
    public SpeechRecognitionParams withEndpointMs(double ms) {
        return new SpeechRecognitionParams(engine, model, moonshineMinConfidence, moonshineStepBonus,
                threads, grammar, adaptation,
                minConfidence, outOfGrammarProbability, garbagePrior, denoise,
                maxPending, minVoicedMs, openAboveFloorDb, minLevelDb, hangoverMs, ms, endpointAboveFloorDb, queue);
    }

    /** These params with another engine. */
    public SpeechRecognitionParams withEngine(String name) {
        return new SpeechRecognitionParams(name, model, moonshineMinConfidence, moonshineStepBonus,
                threads, grammar, adaptation,
                minConfidence,
                outOfGrammarProbability, garbagePrior, denoise, maxPending, minVoicedMs, openAboveFloorDb, minLevelDb,
                hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** These params with another Moonshine model folder. */
    public SpeechRecognitionParams withModel(String folder) {
        return new SpeechRecognitionParams(engine, folder, moonshineMinConfidence, moonshineStepBonus,
                threads, grammar, adaptation,
                minConfidence,
                outOfGrammarProbability, garbagePrior, denoise, maxPending, minVoicedMs, openAboveFloorDb, minLevelDb,
                hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** These params with another Moonshine confidence threshold. */
    public SpeechRecognitionParams withMoonshineMinConfidence(double threshold) {
        return new SpeechRecognitionParams(engine, model, threshold, moonshineStepBonus,
                threads, grammar, adaptation, minConfidence,
                outOfGrammarProbability, garbagePrior, denoise, maxPending, minVoicedMs, openAboveFloorDb, minLevelDb,
                hangoverMs, endpointMs, endpointAboveFloorDb, queue);
    }

    /** The Moonshine model's folder: {@code model}, or the cache folder when it is empty. */
    static Path modelFolder(String model) {
        return model.isEmpty() ? MoonshineFiles.defaultFolder() : Path.of(model);
    }

    /** The threshold of this engine's confidence. */
    double engineMinConfidence() {
        return engine.equals("moonshine") ? moonshineMinConfidence : minConfidence;
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
