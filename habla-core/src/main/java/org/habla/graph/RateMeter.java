package org.habla.graph;

import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.LongAdder;

/** Counts events and tells their rate over the last few seconds (one-second buckets). */
final class RateMeter {

    private static final int SECONDS = 5;

    private final LongAdder total = new LongAdder();
    private final AtomicLongArray buckets = new AtomicLongArray(SECONDS + 1);
    private final AtomicLongArray bucketSecond = new AtomicLongArray(SECONDS + 1);

    void mark(long nowMicros) {
        total.increment();
        long second = nowMicros / 1_000_000;
        int i = (int) (second % buckets.length());
        long owner = bucketSecond.get(i);
        if (owner != second && bucketSecond.compareAndSet(i, owner, second)) {
            buckets.set(i, 0);
        }
        buckets.incrementAndGet(i);
    }

    long total() {
        return total.sum();
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
