package org.habla.graph;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * How much work the graph holds: samples waiting in input slots or being handled, turns queued or running,
 * background tasks under way. A producer counts a sample in before its own turn ends, so the count reaches
 * zero only when every effect of what came in has been handled — the graph is idle. A replay feeds the next
 * recorded reading only then, so every method sees the same sequence as in the recorded run.
 *
 * <p>Only a replay needs the count, and every thread of the graph writes it twice per sample (one counter
 * for the whole graph: the cores hand its cache line back and forth), so a live graph takes {@link #NONE},
 * which counts nothing.
 */
class WorkCount {

    /** Counts nothing: for a graph that nothing waits on (a live one). */
    static final WorkCount NONE = new WorkCount() {
        @Override
        void begin() {
        }

        @Override
        void end() {
        }

        @Override
        boolean awaitIdle(long millis) {
            throw new IllegalStateException("this graph does not count its work: only a replay does");
        }
    };

    private static final long PARK_NANOS = TimeUnit.MICROSECONDS.toNanos(20);

    private final AtomicLong count = new AtomicLong();

    void begin() {
        count.incrementAndGet();
    }

    void end() {
        count.decrementAndGet();
    }

    /** Waits until nothing is in flight; false if that took longer than {@code millis}. */
    boolean awaitIdle(long millis) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        while (count.get() != 0) {
            if (System.nanoTime() - end > 0) {
                return false;
            }
            LockSupport.parkNanos(PARK_NANOS);
            if (Thread.interrupted()) {
                throw new InterruptedException();
            }
        }
        return true;
    }
}
