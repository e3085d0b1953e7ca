package org.habla.methods.speech;

import ai.onnxruntime.OnnxTensor;
import ai.onnxruntime.OrtEnvironment;
import ai.onnxruntime.OrtException;
import ai.onnxruntime.OrtSession;
import java.io.IOException;
import java.nio.FloatBuffer;
import java.nio.LongBuffer;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

/**
 * Moonshine base-en on ONNX Runtime: an encoder that turns 16 kHz audio into hidden states, and a decoder
 * that gives, for token sequences fed whole (teacher forcing), the log-probability of each next token. Both
 * are the ONNX models {@code ./habla models fetch} makes from the wheel's files ({@code .mvn/moonshine_convert.py}):
 * the same network, its 8-bit weights multiplied in 8 bits, the decoder without its cache inputs.
 *
 * <pre>
 *   audio (1 × samples) ─ encoder ─→ hidden (1 × frames × 416)
 *   hidden, repeated B times, and B token rows ─ decoder (no cache) ─→ logits (B × steps × vocab)
 * </pre>
 *
 * <p>Rows are right-padded: the decoder's attention is causal, so a row's padding never changes its earlier
 * steps, and the steps past a row's end are not read. Not safe for two threads at once; one decoder per
 * method.
 */
final class MoonshineModel implements AutoCloseable {

    static final String ENCODER = "encoder.onnx";
    static final String DECODER = "decoder.onnx";
    /** Logits this far below a step's best add less than e^-20 each to its normaliser: left out. */
    private static final float LOG_SUM_RANGE = 20f;

    /**
     * Each scored row: the summed log-probability of its steps (its tokens and its end), the summed shortfall from each
     * step's best, the number of steps, and the lowest log-probability of one step.
     */
    record RowScore(double logProb, double shortfall, int tokens, double worstStep) {
    }

    private final OrtEnvironment env = OrtEnvironment.getEnvironment();
    private final OrtSession encoder;
    private final OrtSession decoder;

    private MoonshineModel(OrtSession encoder, OrtSession decoder) {
        this.encoder = encoder;
        this.decoder = decoder;
    }

    /** Loads both models from {@code dir}, each running on {@code threads} threads. */
    static MoonshineModel load(Path dir, int threads) throws IOException {
        return load(dir.resolve(ENCODER), dir.resolve(DECODER), threads);
    }

    /** Loads the encoder and decoder from their files (ONNX Runtime's format or ONNX), on {@code threads} threads. */
    static MoonshineModel load(Path encoderFile, Path decoderFile, int threads) throws IOException {
        OrtEnvironment env = OrtEnvironment.getEnvironment();
        try {
            OrtSession.SessionOptions o = new OrtSession.SessionOptions();
            o.setIntraOpNumThreads(threads);
            o.setInterOpNumThreads(1);
            o.setOptimizationLevel(OrtSession.SessionOptions.OptLevel.ALL_OPT);
            // Without the arena and the memory pattern, a run's buffers (the logits of every phrase, a long
            // utterance's attention) go back to the system after it instead of staying at their largest.
            o.setCPUArenaAllocator(false);
            o.setMemoryPatternOptimization(false);
            OrtSession enc = env.createSession(encoderFile.toString(), o);
            OrtSession dec = env.createSession(decoderFile.toString(), o);
            return new MoonshineModel(enc, dec);
        } catch (OrtException e) {
            throw new IOException("ONNX Runtime could not load the Moonshine model " + decoderFile.getParent() + ": "
                    + e.getMessage(), e);
        }
    }

    /** The encoder's hidden states for 16 kHz mono audio in [-1, 1]: frames × 416, flattened, and the frame count. */
    Hidden encode(float[] audio) throws OrtException {
        try (OnnxTensor in = OnnxTensor.createTensor(env, FloatBuffer.wrap(audio), new long[] {1, audio.length});
             OrtSession.Result r = encoder.run(Map.of("input_values", in))) {
            OnnxTensor out = (OnnxTensor) r.get(0);
            long[] shape = out.getInfo().getShape();
            FloatBuffer b = out.getFloatBuffer();
            float[] h = new float[b.remaining()];
            b.get(h);
            return new Hidden(h, (int) shape[1], (int) shape[2]);
        }
    }

    /** An utterance's hidden states. */
    record Hidden(float[] values, int frames, int width) {
    }

    /**
     * Scores each row of tokens (without the start token) in one decoder pass: the log-probability of its
     * tokens, then of its end, the step after its last token giving one of {@code enders} (the end token, or
     * punctuation that closes a sentence). The shortfall sums, over the same steps, how far below the step's
     * most likely token the row's token lies (at the end, the likeliest ender): 0 when the row is what the
     * model would say by itself.
     */
    RowScore[] score(Hidden hidden, int[][] rows, int[] enders) throws OrtException {
        int b = rows.length;
        int steps = 0;
        for (int[] row : rows) {
            steps = Math.max(steps, row.length + 1);
        }
        long[] ids = new long[b * steps];
        for (int i = 0; i < b; i++) {
            ids[i * steps] = MoonshineTokenizer.START;
            for (int t = 1; t < steps; t++) {
                ids[i * steps + t] = t - 1 < rows[i].length ? rows[i][t - 1] : MoonshineTokenizer.END;
            }
        }
        float[] states = new float[b * hidden.values().length];
        for (int i = 0; i < b; i++) {
            System.arraycopy(hidden.values(), 0, states, i * hidden.values().length, hidden.values().length);
        }
        Map<String, OnnxTensor> in = new HashMap<>();
        try {
            in.put("input_ids", OnnxTensor.createTensor(env, LongBuffer.wrap(ids), new long[] {b, steps}));
            in.put("encoder_hidden_states", OnnxTensor.createTensor(env, FloatBuffer.wrap(states),
                    new long[] {b, hidden.frames(), hidden.width()}));
            try (OrtSession.Result r = decoder.run(in, java.util.Set.of("logits"))) {
                OnnxTensor logits = (OnnxTensor) r.get(0);
                int vocab = (int) logits.getInfo().getShape()[2];
                FloatBuffer f = logits.getFloatBuffer();
                float[] step = new float[vocab];
                RowScore[] out = new RowScore[b];
                for (int i = 0; i < b; i++) {
                    double lp = 0;
                    double shortfall = 0;
                    double worst = 0;
                    for (int t = 0; t <= rows[i].length; t++) {
                        f.get((i * steps + t) * vocab, step);
                        float max = Float.NEGATIVE_INFINITY;
                        for (float x : step) {
                            max = Math.max(max, x);
                        }
                        double sum = 0;
                        for (float x : step) {
                            if (x - max > -LOG_SUM_RANGE) {
                                sum += Math.exp(x - max);
                            }
                        }
                        double logZ = max + Math.log(sum);
                        double token;
                        if (t < rows[i].length) {
                            token = step[rows[i][t]];
                        } else {
                            double end = 0;
                            for (int e : enders) {
                                end += Math.exp(step[e] - max);
                            }
                            token = max + Math.log(end);
                        }
                        lp += token - logZ;
                        worst = Math.min(worst, token - logZ);
                        shortfall += Math.max(0, max - token);
                    }
                    out[i] = new RowScore(lp, shortfall, rows[i].length + 1, worst);
                }
                return out;
            }
        } finally {
            in.values().forEach(OnnxTensor::close);
        }
    }

    @Override
    public void close() throws OrtException {
        encoder.close();
        decoder.close();
    }
}
