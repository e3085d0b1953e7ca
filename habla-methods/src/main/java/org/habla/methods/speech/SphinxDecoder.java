package org.habla.methods.speech;

import edu.cmu.sphinx.api.AbstractSpeechRecognizer;
import edu.cmu.sphinx.api.Configuration;
import edu.cmu.sphinx.api.Context;
import edu.cmu.sphinx.api.SpeechResult;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.MalformedURLException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.habla.sample.AudioChunk;

/**
 * Sphinx-4 set up for HABLA: the US English acoustic model and pronouncing dictionary of
 * sphinx4-data and a JSGF grammar of the phrases to listen for. Making one loads the model (seconds,
 * tens of megabytes), so the {@code speech-recognition} method makes it in the background, once;
 * each utterance is then decoded in well under a second. Not safe for two threads at once.
 */
public final class SphinxDecoder extends AbstractSpeechRecognizer {

    /** The grammar bundled with HABLA, covering the teacher's vocabulary (a class-path resource). */
    public static final String BUNDLED_GRAMMAR = "/org/habla/methods/speech/commands.gram";

    /** Sphinx-4's own configuration of its components, which HABLA uses with quieter logging. */
    private static final String SPHINX_CONFIG = "/edu/cmu/sphinx/api/default.config.xml";

    private static final String ACOUSTIC_MODEL = "resource:/edu/cmu/sphinx/models/en-us/en-us";
    private static final String DICTIONARY = "resource:/edu/cmu/sphinx/models/en-us/cmudict-en-us.dict";

    /**
     * The word Sphinx puts where it heard something outside the grammar; an utterance with one is
     * not taken for a phrase (noise often decodes as a phrase's first word followed by it).
     */
    private static final String UNKNOWN_WORD = "<unk>";

    /** What Sphinx made of one utterance. */
    public record Decoded(String phrase, double score, long decodeMs) {
    }

    private SphinxDecoder(Context context) throws IOException {
        super(context);
        recognizer.allocate();
    }

    /**
     * Loads the model with the bundled grammar. Sphinx reads grammars from a folder, so the bundled
     * one is copied to a temporary folder first (it may live inside a jar).
     */
    public static SphinxDecoder bundled() throws IOException {
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
        return withGrammarFile(file);
    }

    /** Loads the model with the grammar in a {@code .gram} file (its name without the extension names the grammar). */
    public static SphinxDecoder withGrammarFile(Path gramFile) throws IOException {
        Path file = gramFile.toAbsolutePath().normalize();
        if (!Files.isRegularFile(file)) {
            throw new IOException("grammar file " + file + " does not exist");
        }
        String fileName = file.getFileName().toString();
        String name = fileName.endsWith(".gram") ? fileName.substring(0, fileName.length() - 5) : fileName;
        try {
            String dir = file.getParent().toUri().toURL().toString();
            return load(dir.endsWith("/") ? dir : dir + "/", name);
        } catch (MalformedURLException e) {
            throw new IOException("cannot read grammar " + file + ": " + e.getMessage(), e);
        }
    }

    private static SphinxDecoder load(String grammarLocation, String grammarName) throws IOException {
        Configuration config = new Configuration();
        config.setAcousticModelPath(ACOUSTIC_MODEL);
        config.setDictionaryPath(DICTIONARY);
        config.setGrammarPath(grammarLocation);
        config.setGrammarName(grammarName);
        config.setUseGrammar(true);
        config.setSampleRate(16_000);
        try {
            // The decoder is run over a few seconds of noise first, so the first real utterance is decoded by
            // compiled code (without this the teacher's first command comes seconds late). This leaves no trace
            // on later utterances: the front end keeps no state between them (no endpointer, batch CMN).
            SphinxDecoder d = new SphinxDecoder(new Context(sphinxConfig(), config));
            d.warmUp();
            return d;
        } catch (RuntimeException e) {
            throw new IOException("Sphinx-4 could not load (grammar " + grammarLocation + grammarName + ".gram): "
                    + e.getMessage(), e);
        }
    }

    /**
     * Sphinx's component configuration made fit for HABLA, written to a temporary file because Sphinx
     * reads it by URL: its log level lowered to warnings (at INFO it logs every phone of the model
     * while loading), and its endpointer (speech classifier and marker) taken out of the front end,
     * because HABLA hands it whole utterances already cut by an energy gate: Sphinx's endpointer,
     * made for a live microphone, would cut them again and drop many of them in a noisy room (with
     * it, 49 of the 72 recorded utterances were recognised over white noise at −44 dBFS; without it, 72).
     * For the same reason cepstral mean normalisation is done per utterance (batch) instead of live:
     * the live one carries its estimate from one utterance to the next, so an utterance was heard
     * differently depending on who spoke before it (67–70 of 72 clean utterances in shuffled orders;
     * 71 of 72 in every order per utterance).
     */
    private static String sphinxConfig() throws IOException {
        String xml;
        try (InputStream in = Context.class.getResourceAsStream(SPHINX_CONFIG)) {
            if (in == null) {
                throw new IOException("Sphinx-4's " + SPHINX_CONFIG + " is missing from the class path");
            }
            xml = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        String whole = xml.replaceAll("<item>\\s*speechClassifier\\s*</item>", "")
                .replaceAll("<item>\\s*speechMarker\\s*</item>", "")
                .replaceAll("<item>\\s*liveCMN\\s*</item>", "<item>batchCMN</item>");
        if (whole.contains("<item>speechMarker") || whole.contains("<item>liveCMN") || !whole.contains("batchCMN</item>")) {
            throw new IOException("Sphinx-4's " + SPHINX_CONFIG + " has an unexpected front end; cannot set it up");
        }
        String quiet = whole.replaceFirst("(<property\\s+name=\"logLevel\"\\s+value=)\"[A-Z]+\"", "$1\"WARNING\"");
        Path file = Files.createTempFile("habla-sphinx", ".config.xml");
        Files.writeString(file, quiet, StandardCharsets.UTF_8);
        file.toFile().deleteOnExit();
        return file.toUri().toURL().toString();
    }

    /** Decodes a few seconds of quiet noise, to have the decoding code compiled. */
    private void warmUp() {
        java.util.Random noise = new java.util.Random(16_000);
        byte[] pcm = new byte[16_000 * 2];
        for (int round = 0; round < 3; round++) {
            for (int i = 0; i < pcm.length; i += 2) {
                int v = (int) (noise.nextGaussian() * 200);
                pcm[i] = (byte) v;
                pcm[i + 1] = (byte) (v >> 8);
            }
            decode(AudioChunk.of(org.habla.sample.AudioFormat.MONO_16K, pcm.clone()));
        }
    }

    /**
     * Decodes one utterance of 16 kHz mono 16-bit audio; empty when Sphinx hears no phrase of the
     * grammar in it, or something outside the grammar besides.
     */
    public Optional<Decoded> decode(AudioChunk utterance) {
        if (utterance.format().sampleRateHz() != 16_000 || utterance.format().channels() != 1
                || utterance.format().bitsPerSample() != 16) {
            throw new IllegalArgumentException("Sphinx needs 16 kHz mono 16-bit audio, got " + utterance.format());
        }
        long start = System.nanoTime();
        context.setSpeechSource(new ByteArrayInputStream(utterance.pcm()));
        List<String> words = new ArrayList<>();
        double score = 0;
        boolean outOfGrammar = false;
        SpeechResult result;
        while ((result = getResult()) != null) {
            String hypothesis = result.getHypothesis();
            if (hypothesis != null && hypothesis.contains(UNKNOWN_WORD)) {
                outOfGrammar = true;
            } else if (hypothesis != null && !hypothesis.isBlank()) {
                words.add(hypothesis.trim());
                score += result.getResult().getBestFinalToken() == null ? 0
                        : result.getResult().getBestFinalToken().getScore();
            }
        }
        long ms = (System.nanoTime() - start) / 1_000_000;
        return words.isEmpty() || outOfGrammar ? Optional.empty() : Optional.of(new Decoded(String.join(" ", words), score, ms));
    }
}
