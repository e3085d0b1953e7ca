package org.habla.graph;

import java.util.concurrent.ArrayBlockingQueue;
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

    private final Input<?> input;
    private final AtomicReference<Sample> latest;
    private final ArrayBlockingQueue<Sample> queue;
    private final LongAdder offered = new LongAdder();
    private final LongAdder dropped = new LongAdder();
    private final LongAdder conflated = new LongAdder();
    private final Runnable wake;
    private final WorkCount work;

    InputSlot(Input<?> input, Runnable wake, WorkCount work) {
        this.input = input;
        this.wake = wake;
        this.work = work;
        if (input.delivery().mode() == Delivery.Mode.LATEST) {
            latest = new AtomicReference<>();
            queue = null;
        } else {
            latest = null;
            queue = new ArrayBlockingQueue<>(input.delivery().capacity());
        }
    }

    Input<?> input() {
        return input;
    }

    /** Hands a sample to the method; false if a full queue dropped it. */
    boolean offer(Sample sample) {
        offered.increment();
        boolean taken;
        if (latest != null) {
            work.begin();
            if (latest.getAndSet(sample) != null) {
                conflated.increment();
                work.end();
            }
            taken = true;
        } else {
            work.begin();
            taken = queue.offer(sample);
            if (!taken) {
                work.end();
                dropped.increment();
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
        return latest != null ? latest.getAndSet(null) : queue.poll();
    }

    boolean isEmpty() {
        return latest != null ? latest.get() == null : queue.isEmpty();
    }

    int depth() {
        return latest != null ? (latest.get() == null ? 0 : 1) : queue.size();
    }

    long offered() {
        return offered.sum();
    }

    long dropped() {
        return dropped.sum();
    }

    long conflated() {
        return conflated.sum();
    }
}
