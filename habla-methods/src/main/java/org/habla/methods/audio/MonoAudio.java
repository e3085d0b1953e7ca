package org.habla.methods.audio;

import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;

/**
 * Conversions between audio chunks and mono signals of numbers in [-1, 1): mixing every channel
 * down, changing the sample rate, and back to 16-bit PCM. The audio methods work on one mono
 * signal whatever the robot's microphones deliver (the Aibo's two ears, the Pioneer's one).
 */
public final class MonoAudio {

    /** Half-width of the resampling filter, in input samples at the lower rate. */
    private static final int SINC_HALF_WIDTH = 16;

    private MonoAudio() {
    }

    /** The chunk's channels averaged into one signal. */
    public static double[] mix(AudioChunk chunk) {
        int channels = chunk.format().channels();
        if (channels == 1) {
            return chunk.channel(0);
        }
        double[] mono = new double[chunk.frameCount()];
        for (int c = 0; c < channels; c++) {
            double[] ch = chunk.channel(c);
            for (int i = 0; i < mono.length; i++) {
                mono[i] += ch[i] / channels;
            }
        }
        return mono;
    }

    /**
     * The signal at another sample rate, by windowed-sinc interpolation whose cut-off is the lower
     * of the two Nyquist frequencies (so downsampling does not alias). Same rate: the signal itself.
     */
    public static double[] resample(double[] x, int fromHz, int toHz) {
        if (fromHz == toHz || x.length == 0) {
            return x;
        }
        double ratio = (double) toHz / fromHz;
        int n = (int) Math.floor(x.length * ratio);
        double cutoff = Math.min(1.0, ratio);
        int half = (int) Math.ceil(SINC_HALF_WIDTH / cutoff);
        double[] y = new double[n];
        for (int j = 0; j < n; j++) {
            double t = j / ratio;
            int centre = (int) Math.floor(t);
            double sum = 0;
            for (int i = centre - half + 1; i <= centre + half; i++) {
                if (i < 0 || i >= x.length) {
                    continue;
                }
                double d = t - i;
                double arg = Math.PI * d * cutoff;
                double sinc = Math.abs(arg) < 1e-9 ? 1 : Math.sin(arg) / arg;
                double w = 0.5 + 0.5 * Math.cos(Math.PI * d / (half + 1));
                sum += x[i] * sinc * w * cutoff;
            }
            y[j] = sum;
        }
        return y;
    }

    /** The signal as a mono 16-bit chunk at {@code rateHz}, clipped to the 16-bit range. */
    public static AudioChunk chunk(double[] x, int rateHz) {
        byte[] pcm = new byte[x.length * 2];
        for (int i = 0; i < x.length; i++) {
            long v = Math.round(x[i] * 32768);
            short s = (short) Math.max(Short.MIN_VALUE, Math.min(Short.MAX_VALUE, v));
            pcm[2 * i] = (byte) s;
            pcm[2 * i + 1] = (byte) (s >> 8);
        }
        return AudioChunk.wrap(new AudioFormat(rateHz, 1, 16), pcm);
    }

    /** Root mean square of {@code x}. */
    public static double rms(double[] x) {
        double s = 0;
        for (double v : x) {
            s += v * v;
        }
        return x.length == 0 ? 0 : Math.sqrt(s / x.length);
    }

    /** A level in dB relative to full scale, at least {@code -120}. */
    public static double dbfs(double rms) {
        return Math.max(-120, 20 * Math.log10(Math.max(rms, 1e-12)));
    }
}
