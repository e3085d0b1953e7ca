package org.habla.methods.speech;

/**
 * Trims an utterance to its speech and a fixed margin of what surrounds it, so the recogniser sees the
 * same words the same way whether they came with a little silence or a lot: a recording handed over
 * whole, or a segment cut from a stream. Speech is the stretch from the first to the last
 * {@value #FRAME_MS} ms frame within {@value #SPEECH_RANGE_DB} dB of the loudest.
 */
final class UtteranceTrim {

    static final double FRAME_MS = 10;
    static final double SPEECH_RANGE_DB = 35;
    /** Kept before and after the speech: room for soft onsets and endings. */
    static final double MARGIN_MS = 150;

    private UtteranceTrim() {
    }

    /** {@code mono} (at {@code rateHz}) trimmed to its speech and the margin either side. */
    static double[] trim(double[] mono, int rateHz) {
        int frame = Math.max(1, (int) Math.round(FRAME_MS * rateHz / 1000));
        int frames = mono.length / frame;
        if (frames == 0) {
            return mono;
        }
        double[] energy = new double[frames];
        double peak = 0;
        for (int f = 0; f < frames; f++) {
            double s = 0;
            for (int i = f * frame; i < (f + 1) * frame; i++) {
                s += mono[i] * mono[i];
            }
            energy[f] = s / frame;
            peak = Math.max(peak, energy[f]);
        }
        double threshold = peak * Math.pow(10, -SPEECH_RANGE_DB / 10);
        int first = 0;
        while (first < frames && energy[first] < threshold) {
            first++;
        }
        int last = frames - 1;
        while (last > first && energy[last] < threshold) {
            last--;
        }
        int margin = (int) Math.round(MARGIN_MS * rateHz / 1000);
        int from = Math.max(0, first * frame - margin);
        int to = Math.min(mono.length, (last + 1) * frame + margin);
        return java.util.Arrays.copyOfRange(mono, from, to);
    }
}
