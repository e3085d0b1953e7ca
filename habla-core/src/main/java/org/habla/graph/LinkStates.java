package org.habla.graph;

import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;

/**
 * The one lock under which a link to a robot or to a worker changes state and the staleness of everything
 * that depends on it is brought up to date. The status snapshot takes it too, and an interface publishes its
 * {@code link} record under it after the staleness is in force, so nobody sees a link up while what depends
 * on it is still stale, nor a link record whose {@code stale} flag tells of the state before.
 */
final class LinkStates {

    private final ReentrantLock lock = new ReentrantLock();
    private volatile Runnable refresh = () -> { };

    /** What brings staleness up to date after a change; runs under the lock. Set once the graph is wired. */
    void onChange(Runnable refreshStaleness) {
        this.refresh = refreshStaleness;
    }

    /** Runs {@code change} (a link's state flip and what goes with it) under the lock. */
    void locked(Runnable change) {
        lock.lock();
        try {
            change.run();
        } finally {
            lock.unlock();
        }
    }

    /** Reads a consistent snapshot of link states and staleness. */
    <T> T read(Supplier<T> snapshot) {
        lock.lock();
        try {
            return snapshot.get();
        } finally {
            lock.unlock();
        }
    }

    /** Brings staleness up to date now; only inside {@link #locked}. */
    void refreshStaleness() {
        if (!lock.isHeldByCurrentThread()) {
            throw new IllegalStateException("staleness is refreshed only under the link-state lock");
        }
        refresh.run();
    }
}
