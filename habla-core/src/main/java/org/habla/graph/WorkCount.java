package org.habla.graph;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * How much work the graph holds: samples waiting in input slots or being handled, turns queued or running,
 * background tasks under way. A producer counts a sample in before its own turn ends, so the count reaches
 * zero only when every effect of what came in has been handled — the graph is idle. A replay feeds the next
 * recorded reading only then, so every method sees the same sequence as in the recorded run.
 */
final class WorkCount {

    private static final long PARK_NANOS = TimeUnit.MICROSECONDS.toNanos(20);

    private final AtomicLong count = new AtomicLong();

    void begin() {
        count.incrementAndGet();
    }

    void end() {
        count.decrementAndGet();
    }

    long now() {
        return count.get();
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
