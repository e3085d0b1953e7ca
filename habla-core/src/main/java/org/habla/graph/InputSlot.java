package org.habla.graph;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.LongConsumer;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.sample.Sample;

/**
 * Where samples wait for one input of one method: a single conflating slot for {@code latest}
 * inputs, a bounded queue for {@code queue} inputs. Offers never block; a full queue drops the
 * new sample and counts it. A method run on the thread that delivers to it may take a sample at once, while
 * nothing waits in the slot before it ({@link Taker#takeNow}): it is then handled as if it had been queued and
 * taken, without the queue.
 */
final class InputSlot implements InputEntry {

    /** Who takes the slot's samples: the method's scheduler, through its runner. */
    interface Taker {
        /** A sample is waiting: see that it is handled. */
        void wake();

        /**
         * Hands the {@code arrival}-th sample to the method now, on this thread, if the method is free and nothing
         * waits in {@code slot}; false to queue it instead.
         */
        boolean takeNow(InputSlot slot, Sample sample, long arrival);

        /** A taker that only wakes: every sample is queued. */
        static Taker waking(Runnable wake) {
            return new Taker() {
                @Override
                public void wake() {
                    wake.run();
                }

                @Override
                public boolean takeNow(InputSlot slot, Sample sample, long arrival) {
                    return false;
                }
            };
        }
    }

    /** A sample with its place in the order of arrival at this slot. */
    private record Arrival(Sample sample, long index) {
    }

    private final Input<?> input;
    private final Delivery delivery;
    private final AtomicReference<Arrival> latest;
    private final SlotQueue<Arrival> queue;
    private final AtomicLong offered = new AtomicLong();
    private final LongAdder dropped = new LongAdder();
    private final LongAdder conflated = new LongAdder();
    private final Taker taker;
    private final WorkCount work;
    private final LongConsumer skipped;
    /** Written by whoever takes the method's messages, with release; read by any thread. */
    private volatile long consumedThrough;
    private static final java.lang.invoke.VarHandle CONSUMED_THROUGH;

    static {
        try {
            CONSUMED_THROUGH = java.lang.invoke.MethodHandles.lookup()
                    .findVarHandle(InputSlot.class, "consumedThrough", long.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    InputSlot(Input<?> input, Runnable wake, WorkCount work) {
        this(input, input.delivery(), Taker.waking(wake), work, arrival -> { });
    }

    /**
     * A slot that delivers as {@code delivery}, which may differ from the input's own (a declared cycle's wire),
     * and tells {@code skipped} the place in the order of arrival of every sample that does not reach the method.
     */
    InputSlot(Input<?> input, Delivery delivery, Taker taker, WorkCount work, LongConsumer skipped) {
        this.input = input;
        this.skipped = skipped;
        this.delivery = delivery;
        this.taker = taker;
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
    @Override
    public boolean offer(Sample sample) {
        return offer(sample, arrive());
    }

    /** The next sample's place in the order of arrival (1 for the first); then {@link #offer} or {@link #skip} it. */
    long arrive() {
        return offered.incrementAndGet();
    }

    /** Hands the {@code arrival}-th sample to the method; false if a full queue dropped it. */
    boolean offer(Sample sample, long arrival) {
        if (taker.takeNow(this, sample, arrival)) {
            return true;
        }
        Arrival a = new Arrival(sample, arrival);
        boolean taken;
        if (latest != null) {
            work.begin();
            Arrival replaced = latest.getAndSet(a);
            if (replaced != null) {
                conflated.increment();
                work.end();
                skipped.accept(replaced.index());
            }
            taken = true;
        } else {
            work.begin();
            taken = queue.offer(a);
            if (!taken) {
                work.end();
                dropped.increment();
                skipped.accept(arrival);
            }
        }
        if (taken) {
            taker.wake();
        }
        return taken;
    }

    /**
     * Does not hand the {@code arrival}-th sample to the method, and counts it as this slot counts a sample that does
     * not reach the method: replaced ({@code latest}, returns true) or dropped ({@code queue}, returns false).
     */
    boolean skip(long arrival) {
        skipped.accept(arrival);
        if (latest != null) {
            conflated.increment();
            return true;
        }
        dropped.increment();
        return false;
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
        CONSUMED_THROUGH.setRelease(this, a.index());
        return a.sample();
    }

    /**
     * The {@code arrival}-th sample was handed to the method without waiting here ({@link Taker#takeNow}); counted in
     * as work, as a queued one is. By the thread that holds the method.
     */
    void takenNow(long arrival) {
        work.begin();
        CONSUMED_THROUGH.setRelease(this, arrival);
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
