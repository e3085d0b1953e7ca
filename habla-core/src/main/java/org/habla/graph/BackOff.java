package org.habla.graph;

import java.net.ConnectException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;
import java.util.function.LongConsumer;
import org.habla.config.Reconnect;

/**
 * The wait between connection attempts of a link (to a robot's server or to a worker).
 *
 * <ul>
 *   <li>It starts at {@code initialMs} and doubles after every failed attempt, up to {@code maxMs}: a peer that
 *       does not answer, or accepts and then fails its handshake, is not hammered.</li>
 *   <li>A connect the peer's host refused (nothing listens on the port yet) is an answer that costs it nothing:
 *       the next attempt comes after {@code initialMs} and the doubling starts again. A robot whose server is
 *       restarted is used again within {@code initialMs} and one connect of listening.</li>
 *   <li>Once a session has been up ({@link #reset}), the next wait is {@code initialMs} again, however long the
 *       waits had grown before it.</li>
 * </ul>
 *
 * A wait ends early when the link is told to stop.
 */
final class BackOff {

    private final Reconnect reconnect;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition woken = lock.newCondition();
    private volatile LongConsumer observer = ms -> { };
    private long nextMs;

    BackOff(Reconnect reconnect) {
        this.reconnect = reconnect;
        this.nextMs = reconnect.initialMs();
    }

    /** A session came up: the next wait is the shortest again. */
    void reset() {
        nextMs = reconnect.initialMs();
    }

    /** Tells {@code chosen} every wait as it is chosen (for tests and benchmarks). */
    void observe(LongConsumer chosen) {
        this.observer = chosen;
    }

    /** The wait after an attempt that failed with {@code failure} (or a session that ended with it). */
    long choose(Exception failure) {
        long millis;
        if (refused(failure)) {
            millis = reconnect.initialMs();
            nextMs = Math.min(reconnect.maxMs(), millis * 2);
        } else {
            millis = nextMs;
            nextMs = Math.min(reconnect.maxMs(), nextMs * 2);
        }
        observer.accept(millis);
        return millis;
    }

    /** Whether the peer's host answered the connect with a refusal: it is there, its server is not yet. */
    static boolean refused(Exception failure) {
        return failure instanceof ConnectException && failure.getMessage() != null
                && failure.getMessage().toLowerCase(java.util.Locale.ROOT).contains("refused");
    }

    /**
     * Waits the back-off chosen for {@code failure}, or less if {@link #wake()} is called and {@code keepWaiting}
     * then says no. False if the thread was interrupted (its flag is set again).
     */
    boolean pause(Exception failure, BooleanSupplier keepWaiting) {
        long millis = choose(failure);
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
