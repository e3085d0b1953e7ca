package org.habla.methods.speech;

import java.util.Arrays;
import java.util.Locale;

/**
 * What a {@code speech-recognition} method has heard, for its status line (the daemon's status and the
 * monitor show it as the method's readiness): the engine, utterances cut, decoded, said and rejected (and
 * why), the utterance being cut now, audio waiting or dropped (too many waiting, or waiting too long), and the decoding time's percentiles over the
 * last {@link #WINDOW} utterances. So a teacher who is not heard can see where the chain stops: nothing
 * cut (the detector hears no speech), cut but without voice, decoded but rejected, or queued behind a slow
 * decoder.
 */
final class SpeechStatus {

    /** Decoding times kept for the percentiles. */
    static final int WINDOW = 200;

    private final String engine;
    private final long[] decodeMs = new long[WINDOW];
    long cut;
    long decoded;
    long said;
    long unvoiced;
    long noPhrase;
    long lowConfidence;
    /** Utterances dropped because more than maxPending waited. */
    long dropped;
    /** Utterances dropped because they waited longer than {@link SpeechRecognition#MAX_WAIT_MS}. */
    long late;
    private long times;

    SpeechStatus(String engine) {
        this.engine = engine;
    }

    void decodeTook(long ms) {
        decodeMs[(int) (times++ % WINDOW)] = ms;
    }

    /** The decoding time at quantile {@code q} of the window, or -1 before the first. */
    long decodePercentile(double q) {
        int n = (int) Math.min(times, WINDOW);
        if (n == 0) {
            return -1;
        }
        long[] sorted = Arrays.copyOf(decodeMs, n);
        Arrays.sort(sorted);
        return sorted[Math.min(n - 1, (int) Math.ceil(q * n) - 1 < 0 ? 0 : (int) Math.ceil(q * n) - 1)];
    }

    /** The status line, with the utterance being cut ({@code openMs}, negative when none) and the queue. */
    String line(double openMs, int queued) {
        String decodeTimes = times == 0 ? "no decoding yet"
                : "decoding p50 " + decodePercentile(0.5) + " ms, p99 " + decodePercentile(0.99) + " ms";
        return String.format(Locale.ROOT, "%s: %d utterances cut, %d decoded, %d said; rejected: %d without voice, "
                        + "%d no phrase, %d low confidence; %s; %d queued; dropped: %d over maxPending, %d waited over %d s; "
                        + "%s", engine, cut, decoded, said, unvoiced, noPhrase, lowConfidence, openMs < 0
                        ? "no utterance open" : String.format(Locale.ROOT, "utterance open %.1f s", openMs / 1000), queued,
                dropped, late, SpeechRecognition.MAX_WAIT_MS / 1000, decodeTimes);
    }
}
