package org.habla.methods.sensors;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.Payload;
import org.junit.jupiter.api.Test;

class MicrophoneTest {

    private static final int RATE = 16_000;
    private static final int CHUNK = 320;

    /** Pushes {@code signal} in 20 ms chunks and returns what came out, joined. */
    private static double[] run(MethodHarness h, double[] signal, AudioFormat format) {
        for (int start = 0; start < signal.length; start += CHUNK) {
            int n = Math.min(CHUNK, signal.length - start);
            byte[] pcm = new byte[n * format.frameBytes()];
            for (int i = 0; i < n; i++) {
                short s = (short) Math.max(-32768, Math.min(32767, Math.round(signal[start + i] * 32768)));
                for (int c = 0; c < format.channels(); c++) {
                    int at = (i * format.channels() + c) * 2;
                    pcm[at] = (byte) s;
                    pcm[at + 1] = (byte) (s >> 8);
                }
            }
            h.push("audio", AudioChunk.of(format, pcm));
        }
        return h.values("audio").stream().map(p -> ((AudioChunk) p).channel(0))
                .reduce(new double[0], MicrophoneTest::concat);
    }

    private static double[] concat(double[] a, double[] b) {
        double[] c = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, c, a.length, b.length);
        return c;
    }

    private static double rms(double[] x, int from, int to) {
        double s = 0;
        for (int i = from; i < to; i++) {
            s += x[i] * x[i];
        }
        return Math.sqrt(s / (to - from));
    }

    /** Amplitude of the {@code hz} component over [from, to). */
    private static double toneAmplitude(double[] x, int from, int to, double hz) {
        double re = 0;
        double im = 0;
        for (int i = from; i < to; i++) {
            double a = 2 * Math.PI * hz * i / RATE;
            re += x[i] * Math.cos(a);
            im += x[i] * Math.sin(a);
        }
        return 2 * Math.hypot(re, im) / (to - from);
    }

    private static double[] noise(int n, double sigma, long seed) {
        Random r = new Random(seed);
        double[] x = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = r.nextGaussian() * sigma;
        }
        return x;
    }

    @Test
    void steadyBackgroundNoiseIsAttenuatedOnceTheFloorIsLearnt() {
        MethodHarness h = MethodHarness.started("mic", new Microphone(MicrophoneParams.defaults()));
        double[] in = noise(3 * RATE, 0.05, 1);
        double[] out = run(h, in, AudioFormat.MONO_16K);
        assertThat(out).hasSize(in.length);
        double ratio = rms(out, RATE, 3 * RATE) / rms(in, RATE, 3 * RATE);
        System.out.printf("microphone: noise-only output/input RMS after 1 s = %.3f%n", ratio);
        assertThat(ratio).isLessThan(0.3);
    }

    @Test
    void aToneAboveTheNoisePassesAlmostUnchanged() {
        MethodHarness h = MethodHarness.started("mic", new Microphone(MicrophoneParams.defaults()));
        double[] in = noise(3 * RATE, 0.02, 2);
        int toneStart = 2 * RATE;
        int toneEnd = toneStart + (int) (0.6 * RATE);
        for (int i = toneStart; i < toneEnd; i++) {
            in[i] += 0.3 * Math.sin(2 * Math.PI * 523.25 * i / RATE);
        }
        double[] out = run(h, in, AudioFormat.MONO_16K);
        int from = toneStart + RATE / 50;
        double kept = toneAmplitude(out, from, toneEnd, 523.25) / toneAmplitude(in, from, toneEnd, 523.25);
        double noiseBefore = rms(out, RATE, toneStart) / rms(in, RATE, toneStart);
        System.out.printf("microphone: C5 tone amplitude kept %.3f, noise kept %.3f%n", kept, noiseBefore);
        assertThat(kept).isGreaterThan(0.9);
        assertThat(noiseBefore).isLessThan(0.3);
    }

    @Test
    void aDcOffsetIsRemovedAndStereoIsMixedDownOnRequest() {
        MicrophoneParams p = ParamsJson.of(MicrophoneParams.class, "{\"downmix\": true, \"gate\": false}");
        MethodHarness h = MethodHarness.started("mic", new Microphone(p));
        double[] in = new double[RATE];
        for (int i = 0; i < in.length; i++) {
            in[i] = 0.25 + 0.1 * Math.sin(2 * Math.PI * 1000 * i / RATE);
        }
        double[] out = run(h, in, new AudioFormat(RATE, 2, 16));
        Payload first = h.values("audio").get(0);
        assertThat(((AudioChunk) first).format()).isEqualTo(AudioFormat.MONO_16K);
        double mean = 0;
        for (int i = RATE / 2; i < RATE; i++) {
            mean += out[i] / (RATE / 2.0);
        }
        assertThat(Math.abs(mean)).isLessThan(0.005);
        assertThat(toneAmplitude(out, RATE / 2, RATE, 1000)).isGreaterThan(0.095);
    }
}
