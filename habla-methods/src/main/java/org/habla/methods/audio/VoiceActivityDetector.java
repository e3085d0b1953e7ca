package org.habla.methods.audio;

import java.util.Arrays;

/**
 * Tells, frame by frame, whether a voice is speaking: the level of the speech band (a high-pass at
 * {@value #HIGH_PASS_HZ} Hz takes out hum, rumble and most of a room's low noise) against two
 * statistics of the last {@code noiseWindowMs} of the stream — its floor (the
 * {@value #FLOOR_PERCENTILE}th percentile: the noise between words) and its background (the median:
 * steady noise, or people talking further away). A frame is speech when it stands
 * {@code openAboveFloorDb} above the floor, {@code openAboveBackgroundDb} above the background and at
 * least at {@code minLevelDb}. Both statistics follow the stream whatever it holds, so a detector
 * never locks itself open, and a change of room is learnt within one window.
 *
 * <p>One detector serves one stream at one rate; it keeps the filter state between frames.
 */
public final class VoiceActivityDetector {

    static final double HIGH_PASS_HZ = 200;
    static final double FLOOR_PERCENTILE = 10;
    /** Frames needed before the statistics are trusted; until then nothing is speech. */
    static final int MIN_HISTORY_FRAMES = 4;

    /** The detector's settings: dB and milliseconds. */
    public record Settings(double openAboveFloorDb, double openAboveBackgroundDb, double minLevelDb,
            double noiseWindowMs) {
    }

    private final Settings settings;
    private final double[] history;
    private final double[] sorted;
    private int count;
    private int next;
    // 2nd-order Butterworth high-pass, direct form I
    private final double b0;
    private final double b1;
    private final double b2;
    private final double a1;
    private final double a2;
    private double x1;
    private double x2;
    private double y1;
    private double y2;
    private double floorDb = Double.NaN;
    private double backgroundDb = Double.NaN;

    public VoiceActivityDetector(int rateHz, double frameMs, Settings settings) {
        this.settings = settings;
        int frames = Math.max(MIN_HISTORY_FRAMES, (int) Math.round(settings.noiseWindowMs() / frameMs));
        this.history = new double[frames];
        this.sorted = new double[frames];
        double w = Math.tan(Math.PI * Math.min(HIGH_PASS_HZ, rateHz / 4.0) / rateHz);
        double q = Math.sqrt(2);
        double norm = 1 / (1 + q * w + w * w);
        b0 = norm;
        b1 = -2 * norm;
        b2 = norm;
        a1 = 2 * (w * w - 1) * norm;
        a2 = (1 - q * w + w * w) * norm;
    }

    /** The speech band's level of a frame in dBFS; call once per frame, in order (it filters the stream). */
    public double bandLevelDb(double[] frame) {
        double sum = 0;
        for (double x : frame) {
            double y = b0 * x + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
            x2 = x1;
            x1 = x;
            y2 = y1;
            y1 = y;
            sum += y * y;
        }
        return MonoAudio.dbfs(Math.sqrt(sum / Math.max(1, frame.length)));
    }

    /** Takes the next frame's band level (from {@link #bandLevelDb}); true when it is speech. */
    public boolean isSpeech(double bandDb) {
        remember(bandDb);
        if (count < MIN_HISTORY_FRAMES) {
            return false;
        }
        return bandDb >= openThresholdDb();
    }

    /** The level a frame must reach to be speech now. */
    public double openThresholdDb() {
        return Math.max(settings.minLevelDb(), Math.max(floorDb + settings.openAboveFloorDb(),
                backgroundDb + settings.openAboveBackgroundDb()));
    }

    /** The floor of the last window, in dB (NaN before the first frame). */
    public double floorDb() {
        return floorDb;
    }

    /** The background (median) level of the last window, in dB (NaN before the first frame). */
    public double backgroundDb() {
        return backgroundDb;
    }

    private void remember(double db) {
        history[next] = db;
        next = (next + 1) % history.length;
        count = Math.min(count + 1, history.length);
        System.arraycopy(history, 0, sorted, 0, count);
        Arrays.sort(sorted, 0, count);
        floorDb = sorted[(int) Math.floor((count - 1) * FLOOR_PERCENTILE / 100)];
        backgroundDb = sorted[(count - 1) / 2];
    }
}
