package org.habla.drivers.tekkotsu;

import org.habla.sample.AudioChunk;

/**
 * The conversion of any PCM chunk to the speaker server's mono 16-bit samples at a given rate:
 * channels are averaged, 8-bit samples widened, other rates resampled by linear interpolation.
 */
final class SpeakerPcm {

    private SpeakerPcm() {
    }

    static short[] toMono16(AudioChunk chunk, int rateHz) {
        int channels = chunk.format().channels();
        int frames = chunk.frameCount();
        double[] mono = new double[frames];
        for (int c = 0; c < channels; c++) {
            double[] samples = chunk.channel(c);
            for (int i = 0; i < frames; i++) {
                mono[i] += samples[i] / channels;
            }
        }
        double[] resampled = resample(mono, chunk.format().sampleRateHz(), rateHz);
        short[] out = new short[resampled.length];
        for (int i = 0; i < out.length; i++) {
            out[i] = (short) Math.max(Short.MIN_VALUE, Math.min(Short.MAX_VALUE, Math.round(resampled[i] * 32768.0)));
        }
        return out;
    }

    private static double[] resample(double[] in, int fromHz, int toHz) {
        if (fromHz == toHz || in.length == 0) {
            return in;
        }
        int n = (int) Math.max(1, Math.round((double) in.length * toHz / fromHz));
        double[] out = new double[n];
        double step = (double) fromHz / toHz;
        for (int i = 0; i < n; i++) {
            double at = i * step;
            int lo = (int) Math.floor(at);
            if (lo >= in.length - 1) {
                out[i] = in[in.length - 1];
            } else {
                double frac = at - lo;
                out[i] = in[lo] * (1 - frac) + in[lo + 1] * frac;
            }
        }
        return out;
    }
}
