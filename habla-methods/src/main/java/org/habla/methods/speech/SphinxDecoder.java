// Over 300 lines, on purpose: Sphinx-4 set up once, and both searches of an utterance over the same features.
package org.habla.methods.speech;

import edu.cmu.sphinx.decoder.search.Token;
import edu.cmu.sphinx.frontend.util.StreamDataSource;
import edu.cmu.sphinx.jsgf.JSGFGrammar;
import edu.cmu.sphinx.linguist.acoustic.tiedstate.Sphinx3Loader;
import edu.cmu.sphinx.recognizer.Recognizer;
import edu.cmu.sphinx.result.Result;
import edu.cmu.sphinx.util.LogMath;
import edu.cmu.sphinx.util.props.ConfigurationManager;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;

/**
 * Sphinx-4 set up for HABLA: the US English acoustic model and pronouncing dictionary of sphinx4-data,
 * a JSGF grammar of the phrases to listen for, and HABLA's front end ({@code sphinx.config.xml}).
 * Each utterance is searched twice, over the same features: in the grammar, and as free phones; the
 * phrase's confidence is how close its fit comes to the free phones' (the mean per-frame likelihood
 * ratio, as a number in (0, 1]). Making one loads the model (seconds, tens of megabytes), so the
 * {@code speech-recognition} method makes it in the background, once. Not safe for two threads at once.
 */
public final class SphinxDecoder implements SpeechEngine {

    /** The grammar bundled with HABLA, covering the teacher's vocabulary (a class-path resource). */
    public static final String BUNDLED_GRAMMAR = "/org/habla/methods/speech/commands.gram";

    private static final String CONFIG = "/org/habla/methods/speech/sphinx.config.xml";
    private static final String ACOUSTIC_MODEL = "resource:/edu/cmu/sphinx/models/en-us/en-us";
    private static final String DICTIONARY = "resource:/edu/cmu/sphinx/models/en-us/cmudict-en-us.dict";
    /**
     * Noise added to every utterance before Sphinx hears it, in 16-bit steps (RMS; about −70 dBFS): the
     * log of the mel energies of digital silence is Sphinx's floor value, far from any sound its model
     * knows, and it upset recognition of words that came with digital silence around them (tune voices,
     * clean: 85 % right without, 90 % with; in an echoing room 77 % and 89 %). Seeded afresh for each
     * utterance, so an utterance is heard the same whatever came before it.
     */
    static final double DITHER_RMS = 10;
    private static final long DITHER_SEED = 16_000;

    /**
     * How Sphinx is set up: the grammar, noise removal, the out-of-grammar branch, and the prior of each
     * garbage word ({@link GarbageWords}; 0: none).
     */
    public record Settings(Path grammarFile, boolean denoise, double outOfGrammarProbability,
            double phoneInsertionProbability, double garbagePrior) {
    }

    /**
     * Sphinx-4's loggers named after its classes (outside its configurations' own: see
     * {@link #quiet(ConfigurationManager)}): held here so the level stays set, WARNING so decoding does not fill the
     * log with INFO lines such as each utterance's cepstral mean.
     */
    private static final java.util.logging.Logger SPHINX_LOG = quiet(java.util.logging.Logger.getLogger("edu.cmu.sphinx"));

    private static java.util.logging.Logger quiet(java.util.logging.Logger log) {
        log.setLevel(java.util.logging.Level.WARNING);
        return log;
    }

    /**
     * The parent of a configuration's component loggers (named after its file), at WARNING. Sphinx sets that level
     * itself when it reads the config, but the logging system holds loggers weakly: once collected, the components'
     * loggers fall back to the root's INFO and every utterance logged its cepstral mean. Whoever uses the
     * configuration's components holds the returned logger as long.
     */
    static java.util.logging.Logger quiet(ConfigurationManager cm) {
        String prefix = edu.cmu.sphinx.util.props.ConfigurationManagerUtils.getLogPrefix(cm);
        return quiet(java.util.logging.Logger.getLogger(prefix.substring(0, prefix.length() - 1)));
    }

    private final ConfigurationManager cm;
    private final ConfigurationManager phoneCm;
    /** The two configurations' loggers at WARNING, held as long as their components are. */
    private final List<java.util.logging.Logger> quietLoggers;
    private final Recognizer recognizer;
    private final Recognizer phoneRecognizer;
    private final StreamDataSource source;
    private final StreamDataSource phoneSource;
    private final GrammarPhrases phrases;
    private final LogMath logMath = LogMath.getLogMath();
    /**
     * The free-phone search runs here while the grammar search runs on the caller's thread: one thread,
     * ended when idle for {@link #PHONE_THREAD_IDLE_S} s, so a decoder no longer used leaves none behind.
     */
    private final ExecutorService phoneThread = phoneThread();

    private SphinxDecoder(ConfigurationManager cm, ConfigurationManager phoneCm) throws IOException {
        this.cm = cm;
        this.phoneCm = phoneCm;
        this.quietLoggers = List.of(quiet(cm), quiet(phoneCm));
        this.recognizer = cm.lookup("recognizer");
        // the free-phone linguist reads the model when it is made: load it first
        phoneCm.<edu.cmu.sphinx.linguist.acoustic.AcousticModel>lookup("acousticModel").allocate();
        this.phoneRecognizer = phoneCm.lookup("phoneRecognizer");
        this.source = cm.lookup("dataSource");
        this.phoneSource = phoneCm.lookup("dataSource");
        recognizer.allocate();
        phoneRecognizer.allocate();
        JSGFGrammar grammar = cm.lookup("jsgfGrammar");
        this.phrases = new GrammarPhrases(grammar.getInitialNode());
    }

    /** The bundled grammar as a file (Sphinx reads grammars from a folder; the resource may be in a jar). */
    public static Path bundledGrammar() throws IOException {
        Path dir = Files.createTempDirectory("habla-grammar");
        Path file = dir.resolve("commands.gram");
        try (InputStream in = SphinxDecoder.class.getResourceAsStream(BUNDLED_GRAMMAR)) {
            if (in == null) {
                throw new IOException("the bundled grammar " + BUNDLED_GRAMMAR + " is missing from the class path");
            }
            Files.copy(in, file);
        }
        file.toFile().deleteOnExit();
        dir.toFile().deleteOnExit();
        return file;
    }

    /** Loads the model with these settings and, if given, a speaker's adaptation (an MLLR transform file). */
    public static SphinxDecoder load(Settings settings, Optional<Path> adaptation) throws IOException {
        Path file = settings.grammarFile().toAbsolutePath().normalize();
        Map<String, String> values = new java.util.HashMap<>(values(settings));
        values.put("dictionary", grammarDictionary(settings.grammarFile()).toUri().toURL().toString());
        Map<String, String> phoneValues = new java.util.HashMap<>(values);
        phoneValues.put("useCDUnits", "false");
        try {
            SphinxDecoder d = new SphinxDecoder(new ConfigurationManager(writeConfig(values).toUri().toURL()),
                    new ConfigurationManager(writeConfig(phoneValues).toUri().toURL()));
            if (adaptation.isPresent()) {
                d.adapt(adaptation.get());
            }
            d.warmUp();
            return d;
        } catch (RuntimeException e) {
            throw new IOException("Sphinx-4 could not load (grammar " + file + "): " + e.getMessage(), e);
        }
    }

    private static Map<String, String> values(Settings settings) throws IOException {
        Path file = settings.grammarFile().toAbsolutePath().normalize();
        if (!Files.isRegularFile(file)) {
            throw new IOException("grammar file " + file + " does not exist");
        }
        String fileName = file.getFileName().toString();
        String name = fileName.endsWith(".gram") ? fileName.substring(0, fileName.length() - 5) : fileName;
        String addenda = "";
        if (settings.garbagePrior() > 0) {
            // the grammar, and the grammars beside it it may import, copied with the garbage words added
            Path copy = Files.createTempDirectory("habla-grammar");
            copy.toFile().deleteOnExit();
            try (var siblings = Files.list(file.getParent())) {
                for (Path g : siblings.filter(p -> p.toString().endsWith(".gram")).toList()) {
                    Files.copy(g, copy.resolve(g.getFileName()));
                    copy.resolve(g.getFileName()).toFile().deleteOnExit();
                }
            }
            String jsgf = Files.readString(file, StandardCharsets.UTF_8);
            Map<String, List<String>> garbage = GarbageWords.of(GarbageWords.grammarWords(jsgf), dictionary());
            Files.writeString(copy.resolve(fileName), GarbageWords.augment(jsgf, garbage.keySet(),
                    settings.garbagePrior()), StandardCharsets.UTF_8);
            Path addendum = copy.resolve("garbage.dict");
            Files.writeString(addendum, GarbageWords.addendum(garbage), StandardCharsets.UTF_8);
            addendum.toFile().deleteOnExit();
            addenda = "<property name=\"addenda\" value=\"" + addendum.toUri().toURL() + "\"/>";
            file = copy.resolve(fileName);
        }
        String dir = file.getParent().toUri().toURL().toString();
        return Map.ofEntries(
                Map.entry("addenda", addenda),
                Map.entry("useCDUnits", "true"),
                Map.entry("absoluteBeamWidth", "20000"),
                Map.entry("relativeBeamWidth", "1e-60"),
                Map.entry("wordInsertionProbability", "0.1"),
                Map.entry("silenceInsertionProbability", "0.1"),
                Map.entry("languageWeight", "8.0"),
                Map.entry("outOfGrammarBranch", String.valueOf(settings.outOfGrammarProbability() > 0)),
                Map.entry("outOfGrammarProbability", String.valueOf(Math.max(settings.outOfGrammarProbability(), 1e-300))),
                Map.entry("phoneInsertionProbability", String.valueOf(settings.phoneInsertionProbability())),
                Map.entry("grammarLocation", dir.endsWith("/") ? dir : dir + "/"),
                Map.entry("grammarName", name),
                Map.entry("dictionary", DICTIONARY),
                Map.entry("acousticModel", ACOUSTIC_MODEL),
                Map.entry("denoise", settings.denoise() ? "<item>denoise</item>" : ""),
                Map.entry("cmn", "edu.cmu.sphinx.frontend.feature.BatchCMN"));
    }

    /**
     * The lines of the model's pronouncing dictionary for the words of the grammars in {@code grammar}'s folder
     * (the grammar and those it may import), as a file. Sphinx keeps every line of the dictionary it is given
     * for as long as the recognizer lives, 134 000 words (about 20 MB) for the few dozen a grammar says.
     */
    static Path grammarDictionary(Path grammar) throws IOException {
        java.util.Set<String> words = new java.util.HashSet<>();
        try (var siblings = Files.list(grammar.toAbsolutePath().normalize().getParent())) {
            for (Path g : siblings.filter(p -> p.toString().endsWith(".gram")).toList()) {
                words.addAll(GarbageWords.grammarWords(Files.readString(g, StandardCharsets.UTF_8)));
            }
        }
        String resource = DICTIONARY.substring("resource:".length());
        StringBuilder kept = new StringBuilder();
        try (InputStream in = SphinxDecoder.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IOException("the pronouncing dictionary " + resource + " is missing from the class path");
            }
            var lines = new java.io.BufferedReader(new java.io.InputStreamReader(in, StandardCharsets.UTF_8));
            for (String line; (line = lines.readLine()) != null; ) {
                int space = line.indexOf(' ');
                String word = space < 0 ? line : line.substring(0, space).replaceFirst("\\(\\d+\\)$", "");
                if (words.contains(word.toLowerCase(java.util.Locale.ROOT))) {
                    kept.append(line).append('\n');
                }
            }
        }
        Path file = Files.createTempFile("habla-sphinx", ".dict");
        Files.writeString(file, kept, StandardCharsets.UTF_8);
        file.toFile().deleteOnExit();
        return file;
    }

    /**
     * The pronouncing dictionary of the model, read afresh for each load and let go after it: kept, its
     * 134 000 words as lists of phones were a third of the daemon's live heap (about 50 MB) for good.
     */
    private static Map<String, List<List<String>>> dictionary() throws IOException {
        String resource = DICTIONARY.substring("resource:".length());
        try (InputStream in = SphinxDecoder.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IOException("the pronouncing dictionary " + resource + " is missing from the class path");
            }
            return GarbageWords.readDictionary(in);
        }
    }

    private static Path writeConfig(Map<String, String> values) throws IOException {
        String xml;
        try (InputStream in = SphinxDecoder.class.getResourceAsStream(CONFIG)) {
            if (in == null) {
                throw new IOException(CONFIG + " is missing from the class path");
            }
            xml = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        for (Map.Entry<String, String> e : values.entrySet()) {
            xml = xml.replace("${" + e.getKey() + "}", e.getValue());
        }
        Path file = Files.createTempFile("habla-sphinx", ".config.xml");
        Files.writeString(file, xml, StandardCharsets.UTF_8);
        file.toFile().deleteOnExit();
        return file;
    }

    /** Applies a speaker's MLLR transform (written by {@link #writeAdaptation}) to the loaded model's means. */
    private void adapt(Path transformFile) throws IOException {
        try {
            Mllr transform = Mllr.read(transformFile);
            transform.apply(cm.lookup("acousticModelLoader"));
            transform.apply(phoneCm.lookup("acousticModelLoader"));
        } catch (IOException e) {
            throw new IOException("cannot apply the adaptation " + transformFile + ": " + e.getMessage(), e);
        }
    }

    /**
     * Estimates a speaker's MLLR transform from utterances of theirs (16 kHz mono 16-bit), each aligned to
     * the phrase they were asked to say, and writes it to {@code out}. Returns the frames of speech used.
     * Uses a model of its own (the transform is applied to the means of the model that loads it).
     */
    public static int writeAdaptation(Settings settings, List<AudioChunk> utterances, List<String> phrases, Path out)
            throws IOException {
        return writeAdaptation(settings, utterances, phrases, out, Mllr.PRIOR_FRAMES);
    }

    static int writeAdaptation(Settings settings, List<AudioChunk> utterances, List<String> phrases, Path out,
            double priorFrames) throws IOException {
        if (utterances.size() != phrases.size()) {
            throw new IllegalArgumentException(utterances.size() + " utterances but " + phrases.size() + " phrases");
        }
        ConfigurationManager cm = new ConfigurationManager(writeConfig(values(settings)).toUri().toURL());
        Recognizer aligner = cm.lookup("alignRecognizer");
        edu.cmu.sphinx.linguist.language.grammar.AlignerGrammar grammar = cm.lookup("alignerGrammar");
        StreamDataSource source = cm.lookup("dataSource");
        Sphinx3Loader loader = cm.lookup("acousticModelLoader");
        java.util.logging.Logger quietLog = quiet(cm);
        try {
            // the grammar of each utterance is its phrase; the linguist compiles it again when it changes
            aligner.allocate();
            Mllr.Stats stats = new Mllr.Stats(loader);
            int aligned = 0;
            for (int i = 0; i < utterances.size(); i++) {
                grammar.setWords(List.of(phrases.get(i).trim().split("\\s+")));
                source.setInputStream(new ByteArrayInputStream(dithered(utterances.get(i))));
                Result r = aligner.recognize();
                while (aligner.recognize() != null) {
                    // the rest of the stream
                }
                // the aligner's grammar is the phrase alone: its best path is the alignment
                Token end = r == null ? null : r.getBestFinalToken() != null ? r.getBestFinalToken() : r.getBestToken();
                if (end != null) {
                    stats.collect(end);
                    aligned++;
                }
            }
            if (aligned == 0) {
                throw new IOException("none of the " + utterances.size() + " utterances could be aligned to its phrase");
            }
            Path parent = out.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            stats.estimate(priorFrames).write(out);
            return stats.frames();
        } catch (IOException e) {
            throw e;
        } catch (Exception e) {
            throw new IOException("speaker adaptation failed: " + e.getMessage(), e);
        } finally {
            java.lang.ref.Reference.reachabilityFence(quietLog);
        }
    }

    /** Decodes a few seconds of quiet noise, to have the decoding code compiled before the first utterance. */
    private void warmUp() {
        java.util.Random noise = new java.util.Random(16_000);
        byte[] pcm = new byte[16_000 * 2];
        for (int round = 0; round < 3; round++) {
            for (int i = 0; i < pcm.length; i += 2) {
                int v = (int) (noise.nextGaussian() * 200);
                pcm[i] = (byte) v;
                pcm[i + 1] = (byte) (v >> 8);
            }
            decode(AudioChunk.of(AudioFormat.MONO_16K, pcm.clone()));
        }
    }

    /**
     * Decodes one utterance of 16 kHz mono 16-bit audio: a phrase of the grammar with its confidence,
     * or empty when the search ended outside the grammar (its out-of-grammar branch, or no phrase finished).
     */
    @Override
    public String name() {
        return "sphinx4";
    }

    @Override
    public Optional<Decoded> decode(AudioChunk utterance) {
        if (!utterance.format().equals(AudioFormat.MONO_16K)) {
            throw new IllegalArgumentException("Sphinx needs 16 kHz mono 16-bit audio, got " + utterance.format());
        }
        long start = System.nanoTime();
        Future<Result> free = phoneThread.submit(() -> search(phoneRecognizer, phoneSource, utterance));
        Result r;
        Result freeResult;
        try {
            r = search(recognizer, source, utterance);
        } finally {
            freeResult = await(free);
        }
        Token best = r == null ? null : r.getBestFinalToken();
        if (best == null) {
            return Optional.empty();
        }
        List<String> words = words(best);
        if (words.stream().anyMatch(GarbageWords::isGarbage) || !phrases.accepts(words)) {
            return Optional.empty();
        }
        Token phones = freeResult == null ? null : freeResult.getBestToken();
        double[] g = acoustic(best);
        double confidence = 1;
        if (phones != null && g[1] > 0) {
            double[] p = acoustic(phones);
            double perFrame = logMath.logToLn((float) ((g[0] - p[0]) / g[1]));
            confidence = Math.min(1, Math.exp(perFrame));
        }
        long ms = (System.nanoTime() - start) / 1_000_000;
        return Optional.of(new Decoded(String.join(" ", words), confidence, best.getScore(), ms,
                utterance.frameCount() * 1000L / utterance.format().sampleRateHz()));
    }

    /** The free-phone search's result, once it is done (it always ends: its stream is in memory). */
    private static Result await(Future<Result> search) {
        boolean interrupted = false;
        try {
            while (true) {
                try {
                    return search.get();
                } catch (InterruptedException e) {
                    interrupted = true;
                } catch (ExecutionException e) {
                    throw e.getCause() instanceof RuntimeException re ? re
                            : new IllegalStateException("the free-phone search failed", e.getCause());
                }
            }
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    static final long PHONE_THREAD_IDLE_S = 10;

    private static ExecutorService phoneThread() {
        ThreadPoolExecutor pool = new ThreadPoolExecutor(1, 1, PHONE_THREAD_IDLE_S, TimeUnit.SECONDS,
                new LinkedBlockingQueue<>(), r -> {
                    Thread t = new Thread(r, "habla-sphinx-phones");
                    t.setDaemon(true);
                    t.setPriority(Thread.MIN_PRIORITY); // heavy, like the engine's background work it runs beside
                    return t;
                });
        pool.allowCoreThreadTimeOut(true);
        return pool;
    }

    private static Result search(Recognizer which, StreamDataSource source, AudioChunk utterance) {
        source.setInputStream(new ByteArrayInputStream(dithered(utterance)));
        Result last = null;
        Result r;
        while ((r = which.recognize()) != null) {
            last = r;
            if (r.isFinal() && r.getBestFinalToken() != null) {
                break;
            }
        }
        // drain what is left of the stream so the next search starts afresh
        while (which.recognize() != null) {
            // nothing: the rest of a stream after the final result
        }
        return last;
    }

    /** The utterance's 16-bit PCM with {@link #DITHER_RMS} of noise added (the same noise every time). */
    static byte[] dithered(AudioChunk utterance) {
        byte[] pcm = utterance.pcm().clone();
        java.util.Random r = new java.util.Random(DITHER_SEED);
        for (int i = 0; i + 1 < pcm.length; i += 2) {
            int v = (short) ((pcm[i] & 0xff) | (pcm[i + 1] << 8));
            int d = (int) Math.max(Short.MIN_VALUE, Math.min(Short.MAX_VALUE, Math.round(v + r.nextGaussian() * DITHER_RMS)));
            pcm[i] = (byte) d;
            pcm[i + 1] = (byte) (d >> 8);
        }
        return pcm;
    }

    /** The words of a path, fillers (silence) left out, first word first; {@code <unk>} for the phone loop. */
    private static List<String> words(Token t) {
        List<String> out = new ArrayList<>();
        for (Token at = t; at != null; at = at.getPredecessor()) {
            if (at.isWord()) {
                var w = at.getWord();
                if (!w.isFiller()) {
                    out.add(0, w.getSpelling());
                }
            }
        }
        return out;
    }

    /** The path's summed acoustic score (log base of {@link LogMath}) and its number of frames. */
    private static double[] acoustic(Token t) {
        double sum = 0;
        int frames = 0;
        for (Token at = t; at != null; at = at.getPredecessor()) {
            if (at.isEmitting()) {
                sum += at.getAcousticScore();
                frames++;
            }
        }
        return new double[] {sum, frames};
    }
}
