package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;

/**
 * Latency from a raw reading's time to the moment a method handled a sample derived from it, recorded by one thread
 * at a time (whichever runs the method's messages, each after the one before) and read from any as percentiles over
 * the interval since the last read.
 *
 * <p>A record is one plain increment of a bucket, published with a release store: no atomic read-modify-write and
 * no fence, so the method's every sample costs the thread that handles it nothing it would wait for. Buckets are
 * log-linear ({@value #SUB_BUCKETS} per power of two above {@code 2 × SUB_BUCKETS} µs, one per microsecond below):
 * a value is known to within 1/{@value #SUB_BUCKETS}. The counts only grow; a read takes the difference from the
 * counts it saw the time before, so a sample recorded while it reads is counted in this interval or the next, never
 * lost and never counted twice.
 */
final class LatencyStats {

    static final long MAX_MICROS = 60_000_000L;
    /** Buckets per power of two: a value is known to within 1/128 of itself (under 0.8 %). */
    static final int SUB_BUCKETS = 128;
    private static final int SUB_BITS = Integer.numberOfTrailingZeros(SUB_BUCKETS);
    private static final int BUCKETS = index(MAX_MICROS) + 1;
    private static final VarHandle COUNTS = MethodHandles.arrayElementVarHandle(long[].class);

    /** How many values fell in each bucket since the start; written by the recording thread alone. */
    private final long[] counts = new long[BUCKETS];
    /** The counts at the previous read; the reader's alone. */
    private final long[] seen = new long[BUCKETS];
    /** What was recorded between the previous read and this one; the reader's alone. */
    private final long[] interval = new long[BUCKETS];

    void record(long micros) {
        int i = index(Math.max(0, Math.min(MAX_MICROS, micros)));
        COUNTS.setRelease(counts, i, counts[i] + 1);
    }

    /** Percentiles (µs) over what was recorded since the previous call. */
    synchronized ObjectNode snapshot() {
        long total = 0;
        int highest = -1;
        for (int i = 0; i < BUCKETS; i++) {
            long now = (long) COUNTS.getAcquire(counts, i);
            interval[i] = now - seen[i];
            seen[i] = now;
            if (interval[i] > 0) {
                total += interval[i];
                highest = i;
            }
        }
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("count", total);
        if (total > 0) {
            n.put("p50Us", atPercentile(interval, total, 50));
            n.put("p99Us", atPercentile(interval, total, 99));
            n.put("maxUs", highestIn(highest));
        }
        return n;
    }

    /** The highest value of the bucket below which {@code percentile} % of the {@code total} values fall. */
    private static long atPercentile(long[] buckets, long total, double percentile) {
        long wanted = Math.max(1, (long) Math.ceil(total * percentile / 100.0));
        long below = 0;
        for (int i = 0; i < buckets.length; i++) {
            below += buckets[i];
            if (below >= wanted) {
                return highestIn(i);
            }
        }
        return highestIn(buckets.length - 1);
    }

    /** The bucket of {@code value} (0 ≤ value ≤ {@link #MAX_MICROS}). */
    static int index(long value) {
        if (value < 2 * SUB_BUCKETS) {
            return (int) value;
        }
        int shift = 63 - Long.numberOfLeadingZeros(value) - SUB_BITS;
        return 2 * SUB_BUCKETS + (shift - 1) * SUB_BUCKETS + (int) (value >>> shift) - SUB_BUCKETS;
    }

    /** The highest value that falls in bucket {@code index}. */
    static long highestIn(int index) {
        if (index < 2 * SUB_BUCKETS) {
            return index;
        }
        int shift = (index - 2 * SUB_BUCKETS) / SUB_BUCKETS + 1;
        long mantissa = (index - 2 * SUB_BUCKETS) % SUB_BUCKETS + SUB_BUCKETS;
        return ((mantissa + 1) << shift) - 1;
    }
}
