package org.habla.graph;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;

/**
 * Counts events and tells their rate over the last few seconds (one-second buckets). Marked by one thread at a
 * time (whichever runs a method's messages, each after the one before), so a mark writes its counts without a
 * read-modify-write; read from any thread.
 */
final class RateMeter {

    private static final int SECONDS = 5;

    private final AtomicLong total = new AtomicLong();
    private final AtomicLongArray buckets = new AtomicLongArray(SECONDS + 1);
    private final AtomicLongArray bucketSecond = new AtomicLongArray(SECONDS + 1);

    void mark(long nowMicros) {
        total.setRelease(total.getPlain() + 1);
        long second = nowMicros / 1_000_000;
        int i = (int) (second % buckets.length());
        if (bucketSecond.getPlain(i) != second) {
            buckets.setRelease(i, 0);
            bucketSecond.setRelease(i, second);
        }
        buckets.setRelease(i, buckets.getPlain(i) + 1);
    }

    long total() {
        return total.get();
    }

    /** Events per second over the last full seconds. */
    double perSecond(long nowMicros) {
        long current = nowMicros / 1_000_000;
        long sum = 0;
        for (int i = 0; i < buckets.length(); i++) {
            long s = bucketSecond.get(i);
            if (s < current && s >= current - SECONDS) {
                sum += buckets.get(i);
            }
        }
        return sum / (double) SECONDS;
    }
}
