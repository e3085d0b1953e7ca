package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.HdrHistogram.Histogram;
import org.HdrHistogram.SingleWriterRecorder;

/**
 * Latency from a raw reading's time to the moment a method handled a sample derived from it,
 * recorded without locks by one thread at a time (whichever runs the method's messages) and read from any as
 * percentiles over the interval since the last read.
 */
final class LatencyStats {

    private static final long MAX_MICROS = 60_000_000L;

    private final SingleWriterRecorder recorder = new SingleWriterRecorder(MAX_MICROS, 2);
    private Histogram interval;

    void record(long micros) {
        recorder.recordValue(Math.max(0, Math.min(MAX_MICROS, micros)));
    }

    /** Percentiles (µs) over what was recorded since the previous call. */
    synchronized ObjectNode snapshot() {
        interval = recorder.getIntervalHistogram(interval);
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("count", interval.getTotalCount());
        if (interval.getTotalCount() > 0) {
            n.put("p50Us", interval.getValueAtPercentile(50));
            n.put("p99Us", interval.getValueAtPercentile(99));
            n.put("maxUs", interval.getMaxValue());
        }
        return n;
    }
}
