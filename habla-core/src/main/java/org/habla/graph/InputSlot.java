package org.habla.graph;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.atomic.LongAdder;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.sample.Sample;

/**
 * Where samples wait for one input of one method: a single conflating slot for {@code latest}
 * inputs, a bounded queue for {@code queue} inputs. Offers never block; a full queue drops the
 * new sample and counts it.
 */
final class InputSlot {

    /** A sample with its place in the order of arrival at this slot. */
    private record Arrival(Sample sample, long index) {
    }

    /** Where the slot tells of the samples it skips, and asks which ones a recorded run skipped. */
    interface Skips {
        /** The {@code arrival}-th sample offered never reaches the method (replaced or dropped). */
        void skipped(long arrival);

        /** Whether the run being replayed skipped the {@code arrival}-th sample; false in a live run. */
        boolean skippedWhenRecorded(long arrival);

        Skips NONE = new Skips() {
            @Override
            public void skipped(long arrival) {
            }

            @Override
            public boolean skippedWhenRecorded(long arrival) {
                return false;
            }
        };
    }

    private final Input<?> input;
    private final Delivery delivery;
    private final AtomicReference<Arrival> latest;
    private final SlotQueue<Arrival> queue;
    private final AtomicLong offered = new AtomicLong();
    private final LongAdder dropped = new LongAdder();
    private final LongAdder conflated = new LongAdder();
    private final Runnable wake;
    private final WorkCount work;
    private final Skips skips;
    private volatile long consumedThrough;

    InputSlot(Input<?> input, Runnable wake, WorkCount work) {
        this(input, input.delivery(), wake, work, Skips.NONE);
    }

    /**
     * A slot that delivers as {@code delivery}, which may differ from the input's own (a declared cycle's wire),
     * and tells {@code skips} of every sample that does not reach the method.
     */
    InputSlot(Input<?> input, Delivery delivery, Runnable wake, WorkCount work, Skips skips) {
        this.input = input;
        this.skips = skips;
        this.delivery = delivery;
        this.wake = wake;
        this.work = work;
        if (delivery.mode() == Delivery.Mode.LATEST) {
            latest = new AtomicReference<>();
            queue = null;
        } else {
            latest = null;
            queue = new SlotQueue<>(delivery.capacity());
        }
    }

    Input<?> input() {
        return input;
    }

    /** How this slot delivers. */
    Delivery delivery() {
        return delivery;
    }

    /** Hands a sample to the method; false if a full queue dropped it. */
    boolean offer(Sample sample) {
        Arrival arrival = new Arrival(sample, offered.incrementAndGet());
        if (skips.skippedWhenRecorded(arrival.index())) {
            // A replay: the recorded run replaced or dropped this one before the method took it, so it does too
            // (and says so, for a recording of the replay).
            skips.skipped(arrival.index());
            if (latest != null) {
                conflated.increment();
                return true;
            }
            dropped.increment();
            return false;
        }
        boolean taken;
        if (latest != null) {
            work.begin();
            Arrival replaced = latest.getAndSet(arrival);
            if (replaced != null) {
                conflated.increment();
                work.end();
                skips.skipped(replaced.index());
            }
            taken = true;
        } else {
            work.begin();
            taken = queue.offer(arrival);
            if (!taken) {
                work.end();
                dropped.increment();
                skips.skipped(arrival.index());
            }
        }
        if (taken) {
            wake.run();
        }
        return taken;
    }

    /**
     * The next sample waiting, or null. Called by the method's own thread only, which ends the sample's
     * work count once it has handled it.
     */
    Sample poll() {
        Arrival a = latest != null ? latest.getAndSet(null) : queue.poll();
        if (a == null) {
            return null;
        }
        consumedThrough = a.index();
        return a.sample();
    }

    /**
     * How many of the samples that arrived the method has taken or seen replaced by a newer one it took: what
     * its state reflects, whether or not a {@code latest} slot skipped some.
     */
    long consumedThrough() {
        return consumedThrough;
    }

    boolean isEmpty() {
        return latest != null ? latest.get() == null : queue.isEmpty();
    }

    int depth() {
        return latest != null ? (latest.get() == null ? 0 : 1) : queue.size();
    }

    long offered() {
        return offered.get();
    }

    long dropped() {
        return dropped.sum();
    }

    long conflated() {
        return conflated.sum();
    }
}
