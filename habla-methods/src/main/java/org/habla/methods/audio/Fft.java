package org.habla.methods.audio;

/**
 * A radix-2 fast Fourier transform of real frames, for the spectra the audio methods look at. One
 * instance serves one transform size and keeps its twiddle table and scratch arrays, so it is cheap
 * to call per frame and not safe to share between threads.
 */
public final class Fft {

    private final int size;
    private final double[] cos;
    private final double[] sin;
    private final double[] re;
    private final double[] im;

    /** A transform of {@code size} points, a power of two from 2 to 2^20. */
    public Fft(int size) {
        if (size < 2 || size > (1 << 20) || Integer.bitCount(size) != 1) {
            throw new IllegalArgumentException("FFT size must be a power of two in 2..2^20, was " + size);
        }
        this.size = size;
        this.cos = new double[size / 2];
        this.sin = new double[size / 2];
        for (int k = 0; k < size / 2; k++) {
            cos[k] = Math.cos(-2 * Math.PI * k / size);
            sin[k] = Math.sin(-2 * Math.PI * k / size);
        }
        this.re = new double[size];
        this.im = new double[size];
    }

    /** The smallest power of two of at least {@code n}. */
    public static int sizeFor(int n) {
        int s = 2;
        while (s < n) {
            s <<= 1;
        }
        return s;
    }

    public int size() {
        return size;
    }

    /**
     * The power spectrum |X[k]|², k = 0..size/2, of {@code frame} multiplied by {@code window} (same
     * length as the frame) and zero-padded to the transform size.
     */
    public double[] power(double[] frame, double[] window) {
        if (frame.length > size || window.length != frame.length) {
            throw new IllegalArgumentException("frame of " + frame.length + " with window of " + window.length
                    + " does not fit a " + size + "-point transform");
        }
        java.util.Arrays.fill(re, 0);
        java.util.Arrays.fill(im, 0);
        for (int i = 0; i < frame.length; i++) {
            re[i] = frame[i] * window[i];
        }
        transform();
        double[] p = new double[size / 2 + 1];
        for (int k = 0; k <= size / 2; k++) {
            p[k] = re[k] * re[k] + im[k] * im[k];
        }
        return p;
    }

    /** A Hann window of {@code n} points. */
    public static double[] hann(int n) {
        double[] w = new double[n];
        for (int i = 0; i < n; i++) {
            w[i] = 0.5 - 0.5 * Math.cos(2 * Math.PI * i / Math.max(1, n - 1));
        }
        return w;
    }

    private void transform() {
        for (int i = 1, j = 0; i < size; i++) {
            int bit = size >> 1;
            for (; (j & bit) != 0; bit >>= 1) {
                j ^= bit;
            }
            j ^= bit;
            if (i < j) {
                double t = re[i];
                re[i] = re[j];
                re[j] = t;
                t = im[i];
                im[i] = im[j];
                im[j] = t;
            }
        }
        for (int len = 2; len <= size; len <<= 1) {
            int half = len >> 1;
            int step = size / len;
            for (int start = 0; start < size; start += len) {
                for (int k = 0; k < half; k++) {
                    double wr = cos[k * step];
                    double wi = sin[k * step];
                    int a = start + k;
                    int b = a + half;
                    double xr = re[b] * wr - im[b] * wi;
                    double xi = re[b] * wi + im[b] * wr;
                    re[b] = re[a] - xr;
                    im[b] = im[a] - xi;
                    re[a] += xr;
                    im[a] += xi;
                }
            }
        }
    }
}
