// Over 300 lines, on purpose: gathering, estimating, applying, reading and writing one MLLR transform share its layout.
package org.habla.methods.speech;

import edu.cmu.sphinx.decoder.search.Token;
import edu.cmu.sphinx.frontend.Data;
import edu.cmu.sphinx.frontend.FloatData;
import edu.cmu.sphinx.linguist.HMMSearchState;
import edu.cmu.sphinx.linguist.SearchState;
import edu.cmu.sphinx.linguist.acoustic.HMMState;
import edu.cmu.sphinx.linguist.acoustic.tiedstate.CompositeSenone;
import edu.cmu.sphinx.linguist.acoustic.tiedstate.Senone;
import edu.cmu.sphinx.linguist.acoustic.tiedstate.SenoneHMMState;
import edu.cmu.sphinx.linguist.acoustic.tiedstate.Sphinx3Loader;
import edu.cmu.sphinx.util.LogMath;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Scanner;
import org.apache.commons.math3.linear.Array2DRowRealMatrix;
import org.apache.commons.math3.linear.ArrayRealVector;
import org.apache.commons.math3.linear.LUDecomposition;
import org.apache.commons.math3.linear.RealVector;
import org.apache.commons.math3.linear.SingularMatrixException;

/**
 * A speaker adaptation of the acoustic model's Gaussian means (MLLR: one affine transform per feature
 * stream, {@code mean' = A·mean + b}), estimated from utterances aligned to what the speaker said.
 *
 * <p>HABLA estimates and applies it itself rather than with Sphinx-4 5prealpha's {@code Stats} and
 * {@code Sphinx3Loader.update}, which are wrong for the model sphinx4-data ships (three feature streams
 * of 13, tied mixtures): {@code update} passes every mean through all three streams' transforms one
 * after the other (the delta streams got the cepstra's bias of about 9), and {@code Stats} inverts only
 * the first third of the variances and then weights the rest by the variance instead of its inverse.
 * Here each mean gets its own stream's transform, every Gaussian is weighted by its precision, and the
 * estimate is drawn towards the identity by a prior worth {@link #PRIOR_FRAMES} frames, so a handful of
 * utterances cannot swing it far. The file is Sphinx's MLLR text format (classes, streams, then per stream
 * its length, the rows of A, b, and a variance scale that stays 1).
 */
final class Mllr {

    /**
     * Weight of the prior that draws the transform towards the identity, in frames of speech: with
     * 9 utterances (~900 frames of speech) the data outweighs it ~3 to 1; measured on the tune voices.
     */
    static final double PRIOR_FRAMES = 300;

    private final float[][][] a;
    private final float[][] b;

    private Mllr(float[][][] a, float[][] b) {
        this.a = a;
        this.b = b;
    }

    /** The statistics of one speaker's aligned frames, per stream and row of the transform. */
    static final class Stats {
        private final Sphinx3Loader loader;
        private final LogMath logMath = LogMath.getLogMath();
        private final int streams;
        private final int gaussians;
        private final int[] length;
        /** Per stream, per row k: sum of posterior·precision_k·ξξᵀ (ξ = mean extended by 1). */
        private final double[][][][] g;
        /** Per stream, per row k: sum of posterior·precision_k·x_k·ξ. */
        private final double[][][] z;
        /** Per stream, per row k: sum of posterior·precision_k (the prior is scaled by it). */
        private final double[][] weight;
        private int frames;

        Stats(Sphinx3Loader loader) {
            this.loader = loader;
            this.streams = loader.getNumStreams();
            this.gaussians = loader.getNumGaussiansPerState();
            this.length = loader.getVectorLength();
            this.g = new double[streams][][][];
            this.z = new double[streams][][];
            this.weight = new double[streams][];
            for (int s = 0; s < streams; s++) {
                int n = length[s];
                g[s] = new double[n][n + 1][n + 1];
                z[s] = new double[n][n + 1];
                weight[s] = new double[n];
            }
        }

        /** Adds the frames of the path ending in {@code best} (an alignment). */
        void collect(Token best) {
            for (Token t = best; t != null; t = t.getPredecessor()) {
                SearchState ss = t.getSearchState();
                if (!(ss instanceof HMMSearchState hs) || !ss.isEmitting() || !(t.getData() instanceof FloatData)) {
                    continue;
                }
                Senone senone = senone(hs.getHMMState(), t.getData());
                if (senone == null) {
                    continue;
                }
                int mixture = (int) senone.getID();
                if (loader.hasTiedMixtures()) {
                    mixture = loader.getSenone2Ci()[mixture];
                }
                add(mixture, senone.calculateComponentScore(t.getData()), ((FloatData) t.getData()).getValues());
                frames++;
            }
        }

        /** The senone that scored the frame (of a composite one, its best member). */
        private static Senone senone(HMMState state, Data feature) {
            if (!(state instanceof SenoneHMMState s)) {
                return null;
            }
            Senone senone = s.getSenone();
            if (senone instanceof CompositeSenone c) {
                Senone best = null;
                float bestScore = -Float.MAX_VALUE;
                for (Senone member : c.getSenones()) {
                    float score = member.getScore(feature);
                    if (best == null || score > bestScore) {
                        best = member;
                        bestScore = score;
                    }
                }
                return best;
            }
            return senone;
        }

        private void add(int mixture, float[] componentScores, float[] x) {
            int offset = 0;
            for (int s = 0; s < streams; s++) {
                int n = length[s];
                double[] post = posteriors(componentScores, s * gaussians, gaussians);
                for (int j = 0; j < gaussians; j++) {
                    if (post[j] < 1e-4) {
                        continue;
                    }
                    int index = (mixture * streams + s) * gaussians + j;
                    float[] mean = loader.getMeansPool().get(index);
                    float[] variance = loader.getVariancePool().get(index);
                    for (int k = 0; k < n; k++) {
                        double w = post[j] / Math.max(variance[k], 1e-5f);
                        double wx = w * x[offset + k];
                        double[][] gk = g[s][k];
                        double[] zk = z[s][k];
                        for (int p = 0; p <= n; p++) {
                            double xp = p < n ? mean[p] : 1;
                            zk[p] += wx * xp;
                            for (int q = p; q <= n; q++) {
                                gk[p][q] += w * xp * (q < n ? mean[q] : 1);
                            }
                        }
                        weight[s][k] += w;
                    }
                }
                offset += n;
            }
        }

        private double[] posteriors(float[] scores, int from, int count) {
            double max = -Double.MAX_VALUE;
            for (int j = 0; j < count; j++) {
                max = Math.max(max, scores[from + j]);
            }
            double[] p = new double[count];
            double sum = 0;
            for (int j = 0; j < count; j++) {
                p[j] = logMath.logToLinear((float) (scores[from + j] - max));
                sum += p[j];
            }
            for (int j = 0; j < count; j++) {
                p[j] /= sum;
            }
            return p;
        }

        /** Frames of speech collected. */
        int frames() {
            return frames;
        }

        /**
         * The transform that best explains the frames, each row drawn towards the identity's by a prior
         * worth {@code priorFrames} frames of that row's average precision.
         */
        Mllr estimate(double priorFrames) {
            float[][][] a = new float[streams][][];
            float[][] b = new float[streams][];
            for (int s = 0; s < streams; s++) {
                int n = length[s];
                a[s] = new float[n][n];
                b[s] = new float[n];
                for (int k = 0; k < n; k++) {
                    double[][] m = new double[n + 1][n + 1];
                    double[] v = z[s][k].clone();
                    for (int p = 0; p <= n; p++) {
                        for (int q = p; q <= n; q++) {
                            m[p][q] = g[s][k][p][q];
                            m[q][p] = g[s][k][p][q];
                        }
                    }
                    // the prior: the identity row (A's row k is e_k, b_k is 0), as if seen in priorFrames frames
                    double tau = frames == 0 ? 1 : priorFrames * weight[s][k] / frames;
                    for (int p = 0; p <= n; p++) {
                        m[p][p] += tau * scale(s, p);
                    }
                    v[k] += tau * scale(s, k);
                    RealVector row;
                    try {
                        row = new LUDecomposition(new Array2DRowRealMatrix(m, false)).getSolver()
                                .solve(new ArrayRealVector(v, false));
                    } catch (SingularMatrixException e) {
                        row = new ArrayRealVector(n + 1);
                        row.setEntry(k, 1);
                    }
                    for (int p = 0; p < n; p++) {
                        a[s][k][p] = (float) row.getEntry(p);
                    }
                    b[s][k] = (float) row.getEntry(n);
                }
            }
            return new Mllr(a, b);
        }

        /** Spread of the model's means along dimension p of stream s (1 for the bias): the prior's scale. */
        private double scale(int s, int p) {
            return p < length[s] ? meanSquare(s, p) : 1;
        }

        private double meanSquare(int s, int p) {
            double sum = 0;
            int count = 0;
            int mixtures = loader.getMeansPool().size() / (streams * gaussians);
            for (int m = 0; m < mixtures; m++) {
                for (int j = 0; j < gaussians; j++) {
                    float v = loader.getMeansPool().get((m * streams + s) * gaussians + j)[p];
                    sum += v * v;
                    count++;
                }
            }
            return Math.max(sum / Math.max(1, count), 1e-3);
        }
    }

    /** Applies this transform to the loader's means in place: each mean by the transform of its own stream. */
    void apply(Sphinx3Loader loader) throws IOException {
        int streams = loader.getNumStreams();
        int gaussians = loader.getNumGaussiansPerState();
        if (streams != a.length) {
            throw new IOException("the adaptation is for a model of " + a.length + " feature streams, this one has "
                    + streams);
        }
        for (int s = 0; s < streams; s++) {
            if (a[s].length != loader.getVectorLength()[s]) {
                throw new IOException("the adaptation's stream " + s + " has " + a[s].length + " dimensions, the model's "
                        + loader.getVectorLength()[s]);
            }
        }
        for (int index = 0; index < loader.getMeansPool().size(); index++) {
            int s = (index / gaussians) % streams;
            float[] mean = loader.getMeansPool().get(index);
            float[] adapted = new float[mean.length];
            for (int k = 0; k < mean.length; k++) {
                double v = b[s][k];
                for (int p = 0; p < mean.length; p++) {
                    v += a[s][k][p] * mean[p];
                }
                adapted[k] = (float) v;
            }
            // the Gaussians score against this very array, so they are adapted with it
            System.arraycopy(adapted, 0, mean, 0, mean.length);
        }
    }

    /** The bias of stream s (for reports and tests). */
    float[] bias(int stream) {
        return b[stream].clone();
    }

    /** How far the transform is from the identity: the largest |A − I| entry. */
    double distanceFromIdentity() {
        double d = 0;
        for (int s = 0; s < a.length; s++) {
            for (int k = 0; k < a[s].length; k++) {
                for (int p = 0; p < a[s].length; p++) {
                    d = Math.max(d, Math.abs(a[s][k][p] - (k == p ? 1 : 0)));
                }
            }
        }
        return d;
    }

    /** Writes the transform in Sphinx's MLLR text format (one class). */
    void write(Path file) throws IOException {
        try (PrintWriter w = new PrintWriter(Files.newBufferedWriter(file, StandardCharsets.UTF_8))) {
            w.println(1);
            w.println(a.length);
            for (int s = 0; s < a.length; s++) {
                int n = a[s].length;
                w.println(n);
                for (int k = 0; k < n; k++) {
                    StringBuilder line = new StringBuilder();
                    for (int p = 0; p < n; p++) {
                        line.append(String.format(Locale.ROOT, "%.7g ", a[s][k][p]));
                    }
                    w.println(line.toString().trim());
                }
                StringBuilder bias = new StringBuilder();
                StringBuilder scale = new StringBuilder();
                for (int k = 0; k < n; k++) {
                    bias.append(String.format(Locale.ROOT, "%.7g ", b[s][k]));
                    scale.append("1.0 ");
                }
                w.println(bias.toString().trim());
                w.println(scale.toString().trim());
            }
        }
    }

    /** Reads a transform written by {@link #write} (or Sphinx's MLLR text format of one class). */
    static Mllr read(Path file) throws IOException {
        try (Scanner in = new Scanner(Files.newBufferedReader(file, StandardCharsets.UTF_8))) {
            in.useLocale(Locale.ROOT);
            int classes = in.nextInt();
            if (classes != 1) {
                throw new IOException(file + ": " + classes + " regression classes; HABLA reads adaptations of one");
            }
            int streams = in.nextInt();
            List<float[][]> as = new ArrayList<>();
            List<float[]> bs = new ArrayList<>();
            for (int s = 0; s < streams; s++) {
                int n = in.nextInt();
                float[][] a = new float[n][n];
                float[] b = new float[n];
                for (int k = 0; k < n; k++) {
                    for (int p = 0; p < n; p++) {
                        a[k][p] = finite(file, in.nextFloat());
                    }
                }
                for (int k = 0; k < n; k++) {
                    b[k] = finite(file, in.nextFloat());
                }
                for (int k = 0; k < n; k++) {
                    in.nextFloat();
                }
                as.add(a);
                bs.add(b);
            }
            return new Mllr(as.toArray(new float[0][][]), bs.toArray(new float[0][]));
        } catch (java.util.NoSuchElementException e) {
            throw new IOException(file + " is not an adaptation file written by 'habla enrol' (it ends too soon or "
                    + "holds something other than numbers)", e);
        }
    }

    private static float finite(Path file, float v) throws IOException {
        if (!Float.isFinite(v)) {
            throw new IOException(file + " holds a number that is not finite");
        }
        return v;
    }
}
