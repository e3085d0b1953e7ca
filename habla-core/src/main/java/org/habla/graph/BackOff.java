package org.habla.graph;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;
import org.habla.config.Reconnect;

/**
 * The wait between reconnection attempts of a link (to a robot's server or to a worker): it starts at
 * {@code initialMs}, doubles after every failed attempt up to {@code maxMs}, and returns to the start after
 * a success. A wait ends early when the link is told to stop.
 */
final class BackOff {

    private final Reconnect reconnect;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition woken = lock.newCondition();
    private long nextMs;

    BackOff(Reconnect reconnect) {
        this.reconnect = reconnect;
        this.nextMs = reconnect.initialMs();
    }

    /** An attempt succeeded: the next wait is the shortest again. */
    void reset() {
        nextMs = reconnect.initialMs();
    }

    /**
     * Waits the current back-off, or less if {@link #wake()} is called and {@code keepWaiting} then says no,
     * and doubles the next wait. False if the thread was interrupted (its flag is set again).
     */
    boolean pause(BooleanSupplier keepWaiting) {
        long millis = nextMs;
        nextMs = Math.min(reconnect.maxMs(), nextMs * 2);
        lock.lock();
        try {
            long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
            long left;
            while (keepWaiting.getAsBoolean() && (left = deadline - System.nanoTime()) > 0) {
                woken.awaitNanos(left);
            }
            return true;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        } finally {
            lock.unlock();
        }
    }

    /** Ends a wait in progress early (the waiting side checks whether it should go on). */
    void wake() {
        lock.lock();
        try {
            woken.signalAll();
        } finally {
            lock.unlock();
        }
    }
}
