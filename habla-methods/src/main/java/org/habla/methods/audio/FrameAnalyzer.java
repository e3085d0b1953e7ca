package org.habla.methods.audio;

/**
 * Turns frames of a mono signal into {@link FrameFeatures}: level, YIN pitch and a band spectrum
 * from a Hann-windowed FFT. One analyzer serves one sample rate and frame length.
 */
public final class FrameAnalyzer {

    private final int frameLength;
    private final int bands;
    private final double voicedMinDb;
    private final PitchEstimator pitch;
    private final Fft fft;
    private final double[] window;
    private final double windowEnergy;

    /**
     * @param rateHz      sample rate
     * @param frameLength samples per frame
     * @param bands       number of spectrum bands (1..256)
     * @param minPitchHz  lowest pitch looked for
     * @param maxPitchHz  highest pitch looked for
     * @param aperiodicity largest YIN difference still called periodic
     * @param voicedMinDb quietest level a frame may have and still be voiced
     */
    public FrameAnalyzer(int rateHz, int frameLength, int bands, double minPitchHz, double maxPitchHz,
            double aperiodicity, double voicedMinDb) {
        if (frameLength < 16) {
            throw new IllegalArgumentException("a frame needs at least 16 samples, was " + frameLength);
        }
        this.frameLength = frameLength;
        this.bands = bands;
        this.voicedMinDb = voicedMinDb;
        this.pitch = new PitchEstimator(rateHz, minPitchHz, Math.min(maxPitchHz, rateHz / 2.0 - 1), aperiodicity);
        this.fft = new Fft(Fft.sizeFor(frameLength));
        this.window = Fft.hann(frameLength);
        double e = 0;
        for (double w : window) {
            e += w * w;
        }
        this.windowEnergy = e;
    }

    public int frameLength() {
        return frameLength;
    }

    /** The features of one frame of exactly {@link #frameLength()} samples. */
    public FrameFeatures analyze(double[] frame) {
        if (frame.length != frameLength) {
            throw new IllegalArgumentException("frame of " + frame.length + " samples, expected " + frameLength);
        }
        double rms = MonoAudio.rms(frame);
        double db = MonoAudio.dbfs(rms);
        PitchEstimator.Pitch p = db >= voicedMinDb ? pitch.estimate(frame) : new PitchEstimator.Pitch(0, 1);
        return new FrameFeatures(rms, db, p.hz(), p.voiced(), spectrum(frame));
    }

    private double[] spectrum(double[] frame) {
        double[] power = fft.power(frame, window);
        int n = fft.size();
        double scale = 1.0 / (n * windowEnergy);
        double[] out = new double[bands];
        int bins = power.length;
        for (int b = 0; b < bands; b++) {
            int from = b * bins / bands;
            int to = (b + 1) * bins / bands;
            double sum = 0;
            for (int k = from; k < to; k++) {
                boolean edge = k == 0 || k == bins - 1;
                sum += power[k] * (edge ? 1 : 2);
            }
            out[b] = 10 * Math.log10(Math.max(sum * scale, 1e-12));
        }
        return out;
    }
}
