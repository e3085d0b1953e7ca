package org.habla.monitor;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReferenceArray;
import org.habla.sample.Sample;

/**
 * The newest samples of every method output, kept for the monitor's readers. The engine's threads only write a
 * reference into a fixed ring (no lock, no allocation but the entry); a reader that falls more than a ring behind
 * loses the oldest, which it can tell from the sequence numbers.
 */
final class OutputHistory {

    /** How many of the newest samples are kept per output: 12 s of a 20 Hz stream. */
    static final int SAMPLES_PER_OUTPUT = 256;

    /** One sample and when the monitor saw it (wall clock, µs since the epoch). */
    record Seen(Sample sample, long seenMicros) {
    }

    private static final class Ring {
        private final AtomicReferenceArray<Seen> slots = new AtomicReferenceArray<>(SAMPLES_PER_OUTPUT);
        private final AtomicLong written = new AtomicLong();

        void add(Seen s) {
            long n = written.getAndIncrement();
            slots.set((int) (n % SAMPLES_PER_OUTPUT), s);
        }
    }

    private final Map<String, Ring> rings = new HashMap<>();

    /** @param producers every producer whose samples are kept ({@code method.output}) */
    OutputHistory(List<String> producers) {
        for (String p : producers) {
            rings.put(p, new Ring());
        }
    }

    /** Called on engine threads: keeps the sample if its producer is known. */
    void offer(Sample sample) {
        Ring r = rings.get(sample.producer());
        if (r != null) {
            r.add(new Seen(sample, System.currentTimeMillis() * 1_000));
        }
    }

    /** The newest sample of a producer, or null. */
    Seen latest(String producer) {
        Ring r = rings.get(producer);
        if (r == null) {
            return null;
        }
        long n = r.written.get();
        return n == 0 ? null : r.slots.get((int) ((n - 1) % SAMPLES_PER_OUTPUT));
    }

    /** The kept samples of a producer with a sequence number above {@code afterSequence}, oldest first. */
    List<Seen> since(String producer, long afterSequence) {
        Ring r = rings.get(producer);
        List<Seen> out = new ArrayList<>();
        if (r == null) {
            return out;
        }
        long n = r.written.get();
        for (long i = Math.max(0, n - SAMPLES_PER_OUTPUT); i < n; i++) {
            Seen s = r.slots.get((int) (i % SAMPLES_PER_OUTPUT));
            if (s != null && s.sample().sequence() > afterSequence) {
                out.add(s);
            }
        }
        out.sort((a, b) -> Long.compare(a.sample().sequence(), b.sample().sequence()));
        return out;
    }
}
