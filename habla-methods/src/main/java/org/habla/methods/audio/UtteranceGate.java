package org.habla.methods.audio;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * Cuts utterances and tones out of a stream of frames with an energy gate. It tracks the noise
 * floor (following a falling level quickly and a rising one slowly); the gate opens when a frame is
 * {@code openAboveFloorDb} above the floor and at least {@code minLevelDb}, and closes once the
 * level has stayed below for the hangover, so the short pauses inside a phrase do not split it. A
 * segment carries a little audio from before the gate opened (the preroll: soft onsets such as
 * "f" or "h") and the hangover after; one whose loud part is shorter than {@code minLoudMs} is a
 * click and is dropped, one that reaches {@code maxSegmentMs} is cut there.
 */
public final class UtteranceGate {

    /** The gate's settings, in milliseconds and dB. */
    public record Settings(double openAboveFloorDb, double minLevelDb, double hangoverMs, double prerollMs,
            double minLoudMs, double maxSegmentMs, double floorRiseMs) {
    }

    private final int frameLength;
    private final double frameMs;
    private final Settings settings;
    private final int prerollFrames;
    private final ArrayDeque<double[]> preroll = new ArrayDeque<>();
    private final List<double[]> open = new ArrayList<>();
    private double floorDb = Double.NaN;
    private boolean isOpen;
    private double loudMs;
    private double quietMs;
    private double openMs;

    public UtteranceGate(int rateHz, int frameLength, Settings settings) {
        this.frameLength = frameLength;
        this.frameMs = 1000.0 * frameLength / rateHz;
        this.settings = settings;
        this.prerollFrames = (int) Math.ceil(settings.prerollMs() / frameMs);
    }

    /** The noise floor the gate measures against, in dB (NaN before the first frame). */
    public double floorDb() {
        return floorDb;
    }

    public boolean isOpen() {
        return isOpen;
    }

    /**
     * Takes the next frame with its level; returns a finished segment (mono samples) when this
     * frame closes one.
     */
    public Optional<double[]> offer(double[] frame, double db) {
        if (frame.length != frameLength) {
            throw new IllegalArgumentException("frame of " + frame.length + " samples, expected " + frameLength);
        }
        trackFloor(db);
        boolean loud = db >= Math.max(settings.minLevelDb(), floorDb + settings.openAboveFloorDb());
        if (!isOpen) {
            if (!loud) {
                preroll.addLast(frame);
                while (preroll.size() > prerollFrames) {
                    preroll.removeFirst();
                }
                return Optional.empty();
            }
            isOpen = true;
            open.addAll(preroll);
            preroll.clear();
            loudMs = 0;
            quietMs = 0;
            openMs = 0;
        }
        open.add(frame);
        openMs += frameMs;
        if (loud) {
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

    /** Ends a segment in progress (the stream stopped or changed format); empty if none or too short. */
    public Optional<double[]> flush() {
        return isOpen ? close() : Optional.empty();
    }

    private Optional<double[]> close() {
        isOpen = false;
        double[] joined = new double[open.size() * frameLength];
        for (int i = 0; i < open.size(); i++) {
            System.arraycopy(open.get(i), 0, joined, i * frameLength, frameLength);
        }
        open.clear();
        return loudMs >= settings.minLoudMs() ? Optional.of(joined) : Optional.empty();
    }

    private void trackFloor(double db) {
        if (Double.isNaN(floorDb)) {
            floorDb = db;
            return;
        }
        if (db < floorDb) {
            floorDb = db;
        } else {
            double rise = 1 - Math.exp(-frameMs / settings.floorRiseMs());
            floorDb += (db - floorDb) * rise;
        }
    }
}
