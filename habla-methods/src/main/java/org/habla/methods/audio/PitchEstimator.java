package org.habla.methods.audio;

/**
 * Estimates the fundamental frequency of a frame with the YIN method: the cumulative-mean-normalised
 * difference function, the first lag whose value dips below a threshold, and a parabola through
 * that dip for sub-sample precision. YIN keeps the octave errors of plain autocorrelation rare,
 * which matters for telling a spoken vowel from a whistle or the teacher's notes from each other.
 */
public final class PitchEstimator {

    /** A pitch estimate: frequency (0 when unvoiced) and the normalised difference at the chosen lag (0 = periodic). */
    public record Pitch(double hz, double aperiodicity) {
        public boolean voiced() {
            return hz > 0;
        }
    }

    private final int rateHz;
    private final int minLag;
    private final int maxLag;
    private final double threshold;

    /**
     * @param rateHz    sample rate of the frames
     * @param minHz     lowest pitch looked for; the frame must hold at least twice its period
     * @param maxHz     highest pitch looked for
     * @param threshold largest normalised difference still called periodic (0.1–0.2 is usual)
     */
    public PitchEstimator(int rateHz, double minHz, double maxHz, double threshold) {
        if (!(minHz > 0 && maxHz > minHz && maxHz < rateHz / 2.0)) {
            throw new IllegalArgumentException("pitch range must satisfy 0 < minHz < maxHz < rate/2, was "
                    + minHz + ".." + maxHz + " at " + rateHz + " Hz");
        }
        this.rateHz = rateHz;
        this.minLag = Math.max(2, (int) Math.floor(rateHz / maxHz));
        this.maxLag = (int) Math.ceil(rateHz / minHz);
        this.threshold = threshold;
    }

    /** The number of samples a frame needs for the whole pitch range. */
    public int frameNeeded() {
        return 2 * maxLag + 2;
    }

    /** The pitch of {@code frame}; unvoiced when no lag is periodic enough or the frame is silent. */
    public Pitch estimate(double[] frame) {
        int lags = Math.min(maxLag, frame.length / 2 - 1);
        if (lags <= minLag) {
            return new Pitch(0, 1);
        }
        int window = frame.length - lags;
        double[] d = new double[lags + 1];
        for (int tau = 1; tau <= lags; tau++) {
            double sum = 0;
            for (int i = 0; i < window; i++) {
                double diff = frame[i] - frame[i + tau];
                sum += diff * diff;
            }
            d[tau] = sum;
        }
        double running = 0;
        double[] cmnd = new double[lags + 1];
        cmnd[0] = 1;
        for (int tau = 1; tau <= lags; tau++) {
            running += d[tau];
            cmnd[tau] = running <= 0 ? 1 : d[tau] * tau / running;
        }
        int best = -1;
        for (int tau = minLag; tau <= lags; tau++) {
            if (cmnd[tau] < threshold) {
                while (tau + 1 <= lags && cmnd[tau + 1] < cmnd[tau]) {
                    tau++;
                }
                best = tau;
                break;
            }
        }
        if (best < 0) {
            double min = Double.MAX_VALUE;
            for (int tau = minLag; tau <= lags; tau++) {
                min = Math.min(min, cmnd[tau]);
            }
            return new Pitch(0, Math.min(1, min));
        }
        double lag = best;
        if (best > 1 && best < lags) {
            double a = cmnd[best - 1];
            double b = cmnd[best];
            double c = cmnd[best + 1];
            double denom = a - 2 * b + c;
            if (denom > 0) {
                lag = best + 0.5 * (a - c) / denom;
            }
        }
        return new Pitch(rateHz / lag, cmnd[best]);
    }
}
