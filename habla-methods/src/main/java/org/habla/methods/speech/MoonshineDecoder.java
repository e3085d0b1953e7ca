package org.habla.methods.speech;

import ai.onnxruntime.OrtException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.stream.IntStream;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;

/**
 * The {@code moonshine} engine: Moonshine base-en ({@link MoonshineModel}) held to a JSGF grammar. Each
 * utterance goes through the encoder once; then every phrase of the grammar ({@link GrammarExpansion}),
 * written as a sentence ("Go forward"), is scored in one batched decoder pass, teacher-forced: the
 * log-probability of its tokens and of the sentence ending there (the end token, or "." "!" "?"). The best
 * phrase, by that log-probability plus a bonus per step (without it, in noise, a one-word phrase such as "no"
 * outscores the two-word phrase said: every token costs probability), is the one said, if any.
 *
 * <p>Confidence, for rejecting speech outside the grammar, compares the phrase with what the model would
 * say unconstrained: at each step, how far the phrase's token falls below the step's most likely token,
 * averaged over the steps, as {@code e^-mean} in (0, 1]. It is 1 when the phrase is the model's own
 * transcription, and falls when the model hears other words ("go left" scored as "go back" falls at
 * "back"). It needs no list of out-of-grammar words and nothing from the speaker.
 */
public final class MoonshineDecoder implements SpeechEngine {

    private static final int RATE_HZ = 16_000;
    /** Utterances are scaled to this peak: Moonshine was trained on normalised audio, the teacher's level is not. */
    private static final float PEAK = 0.5f;
    /** Shorter audio is padded with silence to this: the encoder needs a few frames. */
    private static final int MIN_SAMPLES = RATE_HZ / 4;
    /** Pieces that end a sentence, besides the end token. */
    private static final List<String> SENTENCE_ENDS = List.of(".", "!", "?");

    private final MoonshineModel model;
    private final List<String> phrases;
    private final int[][] rows;
    private final int[] enders;
    private final double stepBonus;

    private MoonshineDecoder(MoonshineModel model, List<String> phrases, int[][] rows, int[] enders, double stepBonus) {
        this.model = model;
        this.phrases = phrases;
        this.rows = rows;
        this.enders = enders;
        this.stepBonus = stepBonus;
    }

    /**
     * Loads the model in {@code folder} (its files checked against the pinned sums) for the phrases of
     * {@code grammar}, on {@code threads} threads; the best phrase is the one whose log-probability plus
     * {@code stepBonus} per step (its tokens and its end) is highest.
     */
    public static MoonshineDecoder load(Path grammar, Path folder, int threads, double stepBonus) throws IOException {
        MoonshineFiles.verify(folder);
        List<String> phrases = GrammarExpansion.phrases(grammar);
        MoonshineTokenizer tokenizer = MoonshineTokenizer.load(folder.resolve("tokenizer.json"));
        int[][] rows = phrases.stream().map(p -> tokenizer.encode(sentence(p))).toArray(int[][]::new);
        int[] enders = IntStream.concat(IntStream.of(MoonshineTokenizer.END),
                SENTENCE_ENDS.stream().mapToInt(tokenizer::piece).filter(id -> id >= 0)).toArray();
        MoonshineDecoder d = new MoonshineDecoder(MoonshineModel.load(folder, threads), phrases, rows, enders, stepBonus);
        d.warmUp();
        return d;
    }

    /** How a phrase is written as the model writes a sentence: its first letter capitalised. */
    static String sentence(String phrase) {
        return phrase.substring(0, 1).toUpperCase(Locale.ROOT) + phrase.substring(1);
    }

    /** The grammar's phrases, in the order they are scored. */
    public List<String> phrases() {
        return phrases;
    }

    @Override
    public String name() {
        return "moonshine";
    }

    private void warmUp() {
        decode(AudioChunk.of(AudioFormat.MONO_16K, new byte[RATE_HZ * 2]));
    }

    @Override
    public Optional<Decoded> decode(AudioChunk utterance) {
        if (!utterance.format().equals(AudioFormat.MONO_16K)) {
            throw new IllegalArgumentException("Moonshine needs 16 kHz mono 16-bit audio, got " + utterance.format());
        }
        long start = System.nanoTime();
        float[] audio = normalised(utterance);
        MoonshineModel.RowScore[] scores;
        try {
            scores = model.score(model.encode(audio), rows, enders);
        } catch (OrtException e) {
            throw new IllegalStateException("ONNX Runtime failed on an utterance: " + e.getMessage(), e);
        }
        int best = best(scores, stepBonus);
        MoonshineModel.RowScore s = scores[best];
        double confidence = Math.exp(-s.shortfall() / s.tokens());
        long ms = (System.nanoTime() - start) / 1_000_000;
        return Optional.of(new Decoded(phrases.get(best), confidence, s.logProb(), ms,
                utterance.frameCount() * 1000L / RATE_HZ));
    }

    /** The index of the best row: the highest log-probability plus {@code stepBonus} per step. */
    static int best(MoonshineModel.RowScore[] scores, double stepBonus) {
        int best = 0;
        for (int i = 1; i < scores.length; i++) {
            if (scores[i].logProb() + stepBonus * scores[i].tokens()
                    > scores[best].logProb() + stepBonus * scores[best].tokens()) {
                best = i;
            }
        }
        return best;
    }

    /** The utterance as the encoder takes it: floats scaled to {@link #PEAK}, padded to a quarter second. */
    static float[] normalised(AudioChunk utterance) {
        double[] samples = utterance.channel(0);
        int n = samples.length;
        float[] audio = new float[Math.max(n, MIN_SAMPLES)];
        float peak = 0;
        for (int i = 0; i < n; i++) {
            audio[i] = (float) samples[i];
            peak = Math.max(peak, Math.abs(audio[i]));
        }
        if (peak > 0) {
            for (int i = 0; i < n; i++) {
                audio[i] *= PEAK / peak;
            }
        }
        return audio;
    }

    @Override
    public void close() {
        try {
            model.close();
        } catch (OrtException e) {
            throw new IllegalStateException(e);
        }
    }
}
