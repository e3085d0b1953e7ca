package org.habla.methods.notes;

import java.util.Arrays;
import java.util.Optional;
import java.util.Set;
import org.habla.methods.audio.Fft;

/**
 * Finds the note a frame of sound holds, if it holds one clearly. It takes the strongest peak of
 * the Hann-windowed, zero-padded spectrum within the note range, refines its frequency with a
 * parabola through the log power of the peak and its neighbours, and accepts it when it stands
 * {@code minSnrDb} above the median power of the range (a tone is one narrow peak; noise spreads
 * evenly, so its strongest bin stays near the median), lies within {@code toleranceCents} of a note
 * and that note is allowed.
 */
final class ToneDetector {

    /** How many times the transform is longer than the frame: finer bins for the peak search. */
    private static final int ZERO_PADDING = 4;

    private final int rateHz;
    private final Fft fft;
    private final double[] window;
    private final int fromBin;
    private final int toBin;
    private final double minSnr;
    private final double a4Hz;
    private final double toleranceCents;
    private final Set<Note> allowed;

    ToneDetector(int rateHz, int frameLength, NoteRecognitionParams params, Set<Note> allowed) {
        this.rateHz = rateHz;
        this.fft = new Fft(Fft.sizeFor(frameLength * ZERO_PADDING));
        this.window = Fft.hann(frameLength);
        double binHz = (double) rateHz / fft.size();
        this.fromBin = Math.max(2, (int) Math.floor(params.minHz() / binHz));
        this.toBin = Math.min(fft.size() / 2 - 2, (int) Math.ceil(Math.min(params.maxHz(), rateHz / 2.0) / binHz));
        this.minSnr = Math.pow(10, params.minSnrDb() / 10);
        this.a4Hz = params.referenceA4Hz();
        this.toleranceCents = params.toleranceCents();
        this.allowed = allowed;
    }

    /** The note the frame holds, or empty. */
    Optional<Note> detect(double[] frame) {
        if (toBin <= fromBin) {
            return Optional.empty();
        }
        double[] p = fft.power(frame, window);
        int peak = fromBin;
        for (int k = fromBin; k <= toBin; k++) {
            if (p[k] > p[peak]) {
                peak = k;
            }
        }
        double[] range = Arrays.copyOfRange(p, fromBin, toBin + 1);
        Arrays.sort(range);
        double median = range[range.length / 2];
        if (!(p[peak] > 0) || p[peak] < minSnr * Math.max(median, 1e-30)) {
            return Optional.empty();
        }
        double a = Math.log(Math.max(p[peak - 1], 1e-30));
        double b = Math.log(p[peak]);
        double c = Math.log(Math.max(p[peak + 1], 1e-30));
        double denom = a - 2 * b + c;
        double offset = denom < 0 ? 0.5 * (a - c) / denom : 0;
        double hz = (peak + offset) * rateHz / fft.size();
        Note note = Note.nearest(hz, a4Hz);
        if (Math.abs(note.centsFrom(hz, a4Hz)) > toleranceCents) {
            return Optional.empty();
        }
        return allowed.isEmpty() || allowed.contains(note) ? Optional.of(note) : Optional.empty();
    }
}
