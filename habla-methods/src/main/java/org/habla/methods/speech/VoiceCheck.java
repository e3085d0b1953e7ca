package org.habla.methods.speech;

import org.habla.methods.audio.PitchEstimator;

/**
 * Tells whether an utterance holds a voice before it costs a decoder's turn: a voice is periodic with
 * a pitch between {@value #MIN_PITCH_HZ} and {@value #MAX_PITCH_HZ} Hz for some time, while a door
 * banging, wind or a whistled note is not. Sphinx, bound to a grammar, would otherwise name a phrase
 * for almost any sound it is given.
 */
final class VoiceCheck {

    static final double MIN_PITCH_HZ = 70;
    static final double MAX_PITCH_HZ = 500;
    /**
     * The pitch search reaches well above a voice, so that a high whistle is found at its own pitch
     * rather than at a subharmonic that would pass for a voice.
     */
    private static final double SEARCH_MAX_HZ = 2000;
    private static final double FRAME_MS = 32;
    private static final double APERIODICITY = 0.2;

    private final double minVoicedMs;

    /** @param minVoicedMs how much voiced sound an utterance needs; 0 takes every utterance */
    VoiceCheck(double minVoicedMs) {
        this.minVoicedMs = minVoicedMs;
    }

    /** Whether {@code mono} (at {@code rateHz}) holds at least the minimum of voiced sound. */
    boolean hasVoice(double[] mono, int rateHz) {
        if (minVoicedMs <= 0) {
            return true;
        }
        int frame = (int) Math.round(FRAME_MS * rateHz / 1000);
        PitchEstimator pitch = new PitchEstimator(rateHz, Math.max(MIN_PITCH_HZ, 2.0 * rateHz / frame),
                Math.min(SEARCH_MAX_HZ, rateHz / 2.0 - 1), APERIODICITY);
        double voicedMs = 0;
        double[] f = new double[frame];
        for (int start = 0; start + frame <= mono.length; start += frame) {
            System.arraycopy(mono, start, f, 0, frame);
            double hz = pitch.estimate(f).hz();
            if (hz >= MIN_PITCH_HZ && hz <= MAX_PITCH_HZ) {
                voicedMs += FRAME_MS;
                if (voicedMs >= minVoicedMs) {
                    return true;
                }
            }
        }
        return false;
    }
}
