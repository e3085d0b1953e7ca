package org.habla.methods.audio;

import java.util.Arrays;
import java.util.Random;
import org.habla.method.MethodHarness;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;

/** Synthesised test sounds and a way to stream them into a method in chunks. */
final class Signals {

    private Signals() {
    }

    static double[] tone(double hz, double amplitude, double seconds, int rateHz) {
        double[] x = new double[(int) Math.round(seconds * rateHz)];
        for (int i = 0; i < x.length; i++) {
            x[i] = amplitude * Math.sin(2 * Math.PI * hz * i / rateHz);
        }
        return x;
    }

    static double[] noise(double sigma, double seconds, int rateHz, Random random) {
        double[] x = new double[(int) Math.round(seconds * rateHz)];
        for (int i = 0; i < x.length; i++) {
            x[i] = random.nextGaussian() * sigma;
        }
        return x;
    }

    static double[] silence(double seconds, int rateHz) {
        return new double[(int) Math.round(seconds * rateHz)];
    }

    static double[] concat(double[]... parts) {
        int n = Arrays.stream(parts).mapToInt(p -> p.length).sum();
        double[] out = new double[n];
        int at = 0;
        for (double[] p : parts) {
            System.arraycopy(p, 0, out, at, p.length);
            at += p.length;
        }
        return out;
    }

    static double[] add(double[] a, double[] b) {
        double[] out = a.clone();
        for (int i = 0; i < Math.min(a.length, b.length); i++) {
            out[i] += b[i];
        }
        return out;
    }

    /** The signal as 16-bit PCM with every channel equal. */
    static byte[] pcm(double[] x, int from, int to, int channels) {
        byte[] pcm = new byte[(to - from) * channels * 2];
        for (int i = from; i < to; i++) {
            short s = (short) Math.max(-32768, Math.min(32767, Math.round(x[i] * 32768)));
            for (int c = 0; c < channels; c++) {
                int at = ((i - from) * channels + c) * 2;
                pcm[at] = (byte) s;
                pcm[at + 1] = (byte) (s >> 8);
            }
        }
        return pcm;
    }

    /**
     * Pushes {@code x} into input {@code input} in chunks of {@code chunkMs}, each stamped with its
     * stream time from {@code startMicros}; the harness clock is not moved.
     */
    static void stream(MethodHarness h, String input, double[] x, AudioFormat format, double chunkMs,
            long startMicros) {
        int chunk = Math.max(1, (int) Math.round(chunkMs * format.sampleRateHz() / 1000));
        for (int start = 0; start < x.length; start += chunk) {
            int end = Math.min(x.length, start + chunk);
            long t = startMicros + Math.round(start * 1e6 / format.sampleRateHz());
            h.push(input, AudioChunk.wrap(format, pcm(x, start, end, format.channels())), t);
        }
    }
}
