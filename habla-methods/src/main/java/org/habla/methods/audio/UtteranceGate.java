package org.habla.methods.audio;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Cuts utterances out of a stream with a {@link VoiceActivityDetector}, deciding every
 * {@value #FRAME_MS} ms whatever blocks the audio comes in. The gate opens on
 * the first speech frame and closes once no frame has been speech for the hangover, so the short
 * pauses inside a phrase do not split it; a frame counts as speech while the gate is open if it stays
 * within {@code closeBelowOpenDb} of the detector's threshold (hysteresis) and within
 * {@code peakRangeDb} of the loudest frame so far (so a room's echo, dying away, does not hold the
 * gate open). A segment carries {@code prerollMs} of audio from before the gate opened (soft onsets
 * such as "f" or "h") and the hangover after; one with less than {@code minLoudMs} of speech is a
 * click and is dropped, one that reaches {@code maxSegmentMs} is cut there.
 */
public final class UtteranceGate {

    /** The detector's frame: short, so the end of speech is seen within this much. */
    public static final double FRAME_MS = 10;

    /** A finished segment: its samples, its number (counting from 1) and how much of it was speech. */
    public record Segment(double[] samples, long number, double loudMs) {
    }

    /** The gate's settings, in milliseconds and dB. */
    public record Settings(VoiceActivityDetector.Settings detector, double closeBelowOpenDb, double peakRangeDb,
            double hangoverMs, double prerollMs, double minLoudMs, double maxSegmentMs) {
    }

    private final int frameLength;
    private final double frameMs;
    private final Settings settings;
    private final VoiceActivityDetector detector;
    private final int prerollFrames;
    private final ArrayDeque<double[]> preroll = new ArrayDeque<>();
    private double[] frame;
    private int fill;
    private final List<double[]> open = new ArrayList<>();
    private boolean isOpen;
    private double openThresholdDb;
    private double peakDb;
    private double loudMs;
    private double quietMs;
    private double openMs;
    private long segments;

    public UtteranceGate(int rateHz, Settings settings) {
        this.frameLength = Math.max(1, (int) Math.round(FRAME_MS * rateHz / 1000));
        this.frame = new double[frameLength];
        this.frameMs = 1000.0 * frameLength / rateHz;
        this.settings = settings;
        this.detector = new VoiceActivityDetector(rateHz, frameMs, settings.detector());
        this.prerollFrames = (int) Math.ceil(settings.prerollMs() / frameMs);
    }

    /** The noise floor the detector measures against, in dB (NaN before the first frame). */
    public double floorDb() {
        return detector.floorDb();
    }

    public boolean isOpen() {
        return isOpen;
    }

    /** Takes the next samples of the stream (any number); returns the segments (mono samples) they finish. */
    public List<double[]> offer(double[] samples) {
        return offerSegments(samples).stream().map(Segment::samples).toList();
    }

    /** The number of the segment open now or last opened (0 before the first). */
    public long segmentNumber() {
        return segments;
    }

    /** Speech heard so far in the open segment, in ms. */
    public double loudMs() {
        return isOpen ? loudMs : 0;
    }

    /** How long the open segment has been open, in ms (0 when the gate is shut). */
    public double openMs() {
        return isOpen ? openMs : 0;
    }

    /** How long the open segment has been without speech, in ms (0 while speech goes on or the gate is shut). */
    public double quietMs() {
        return isOpen ? quietMs : 0;
    }

    /** How far the open segment's loudest frame stands above the noise floor, in dB (0 when the gate is shut). */
    public double peakAboveFloorDb() {
        return isOpen ? peakDb - detector.floorDb() : 0;
    }

    /** The audio of the open segment so far (pre-roll included); empty when the gate is shut. */
    public double[] soFar() {
        return isOpen ? joined() : new double[0];
    }

    /** As {@link #offer}, with each segment's number and speech. */
    public List<Segment> offerSegments(double[] samples) {
        List<Segment> done = new ArrayList<>(1);
        int at = 0;
        while (at < samples.length) {
            int take = Math.min(frameLength - fill, samples.length - at);
            System.arraycopy(samples, at, frame, fill, take);
            fill += take;
            at += take;
            if (fill == frameLength) {
                double[] full = frame;
                frame = new double[frameLength];
                fill = 0;
                offerFrame(full).ifPresent(done::add);
            }
        }
        return done;
    }

    private Optional<Segment> offerFrame(double[] frame) {
        double db = detector.bandLevelDb(frame);
        boolean speech = detector.isSpeech(db);
        if (!isOpen) {
            if (!speech) {
                preroll.addLast(frame);
                while (preroll.size() > prerollFrames) {
                    preroll.removeFirst();
                }
                return Optional.empty();
            }
            isOpen = true;
            segments++;
            open.addAll(preroll);
            preroll.clear();
            openThresholdDb = detector.openThresholdDb();
            peakDb = db;
            loudMs = 0;
            quietMs = 0;
            openMs = 0;
        }
        open.add(frame);
        openMs += frameMs;
        peakDb = Math.max(peakDb, db);
        boolean voiced = db >= Math.max(openThresholdDb - settings.closeBelowOpenDb(), peakDb - settings.peakRangeDb());
        if (voiced) {
            loudMs += frameMs;
            quietMs = 0;
        } else {
            quietMs += frameMs;
        }
        if (quietMs >= settings.hangoverMs() || openMs >= settings.maxSegmentMs()) {
            return close();
        }
        return Optional.empty();
    }

    /**
     * Ends the open segment here without giving it out (its listener has already dealt with it, e.g. heard
     * a whole phrase in it before the hangover ran out); speech after this opens a new one.
     */
    public void cut() {
        if (isOpen) {
            isOpen = false;
            open.clear();
            preroll.clear();
        }
    }

    /** Ends a segment in progress (the stream stopped or changed format); empty if none or too short. */
    public Optional<double[]> flush() {
        return isOpen ? close().map(Segment::samples) : Optional.empty();
    }

    private Optional<Segment> close() {
        isOpen = false;
        double[] joined = joined();
        open.clear();
        return loudMs >= settings.minLoudMs() ? Optional.of(new Segment(joined, segments, loudMs)) : Optional.empty();
    }

    private double[] joined() {
        double[] joined = new double[open.size() * frameLength];
        for (int i = 0; i < open.size(); i++) {
            System.arraycopy(open.get(i), 0, joined, i * frameLength, frameLength);
        }
        return joined;
    }
}
