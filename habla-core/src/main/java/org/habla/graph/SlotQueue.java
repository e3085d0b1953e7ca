package org.habla.graph;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.AtomicReferenceArray;

/**
 * The bounded queue of a {@code queue} input: any number of threads offer, the method's own thread alone
 * takes. No lock: a producer claims a place by advancing the tail, fills the cell and marks it full; the
 * consumer takes a cell once it is marked full and marks it free for the producer one lap later. Each cell
 * carries the position it is ready for, so a producer and the consumer touch the same cache line only when
 * the queue is nearly empty or nearly full (the lock of {@code ArrayBlockingQueue} was one line for both ends,
 * and every offer and take wrote it).
 *
 * @param <T> what waits
 */
final class SlotQueue<T> {

    private final int capacity;
    /** Cells in the ring: the capacity, but at least two (one cell could not tell "filled" from "free again"). */
    private final int ring;
    private final AtomicReferenceArray<T> cells;
    /**
     * For each cell, the position it is ready for: {@code p} to be filled at position p, {@code p + 1} to be
     * taken (a ring of at least two keeps the two apart).
     */
    private final AtomicLongArray ready;
    /** The next position a producer claims. */
    private final AtomicLong tail = new AtomicLong();
    /** The next position the consumer takes; written by the consumer only, with release (see {@link #poll}). */
    private volatile long head;
    private static final java.lang.invoke.VarHandle HEAD;

    static {
        try {
            HEAD = java.lang.invoke.MethodHandles.lookup().findVarHandle(SlotQueue.class, "head", long.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    SlotQueue(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity must be at least 1, was " + capacity);
        }
        this.capacity = capacity;
        this.ring = Math.max(2, capacity);
        this.cells = new AtomicReferenceArray<>(ring);
        this.ready = new AtomicLongArray(ring);
        for (int i = 0; i < ring; i++) {
            ready.set(i, i);
        }
    }

    /** Adds {@code value} at the tail; false, leaving the queue as it was, if {@code capacity} values wait. */
    boolean offer(T value) {
        long pos = tail.get();
        while (true) {
            int cell = (int) (pos % ring);
            long lag = ready.getAcquire(cell) - pos;
            if (lag == 0 && ring > capacity && pos - head >= capacity) {
                return false;   // a queue of one, full: its ring has a second cell that must stay empty
            }
            if (lag == 0) {
                if (tail.compareAndSet(pos, pos + 1)) {
                    cells.setPlain(cell, value);
                    ready.setRelease(cell, pos + 1);
                    return true;
                }
                pos = tail.get();
            } else if (lag < 0) {
                return false;   // the cell still holds the value from one lap ago: full
            } else {
                pos = tail.get();   // another producer took this position
            }
        }
    }

    /** The value at the head, removed; null if none is there yet. From the consumer's thread only. */
    T poll() {
        long pos = head;
        int cell = (int) (pos % ring);
        if (ready.getAcquire(cell) != pos + 1) {
            return null;
        }
        T value = cells.getPlain(cell);
        cells.setPlain(cell, null);
        ready.setRelease(cell, pos + ring);
        // Release, not a full fence: a producer that reads an older head only finds the queue a place fuller for a
        // moment, as it would had it looked a moment earlier; the consumer reads its own writes.
        HEAD.setRelease(this, pos + 1);
        return value;
    }

    /**
     * Whether no producer has claimed a place the consumer has not taken. A claimed place may not be filled
     * yet (then {@link #poll} returns null for a moment); the tail is read as a volatile, so a thread that
     * announced it will sleep and then finds the queue empty is seen by any producer that claims after.
     */
    boolean isEmpty() {
        return tail.get() == head;
    }

    /** How many values wait (claimed places included); exact when no producer is in the middle of an offer. */
    int size() {
        return (int) Math.max(0, Math.min(capacity, tail.get() - head));
    }
}
