package org.habla.graph;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.LongSupplier;
import org.habla.sample.Sample;

/**
 * One method's messages and the order in which it takes them: a pass takes at most one sample from every input slot
 * (round robin), then the turns — ticks, background results, a change of placement — that were waiting when the
 * turns began, and hands each to where the method runs ({@link MethodHost}), one message at a time. Before each
 * message the method hears of a motion reset it has not heard of yet. Which thread runs the passes is the one
 * thing that differs: a thread of the method's own, woken by whoever adds work ({@link OwnThreadScheduler}), or the
 * thread that delivers to the method, right away ({@link InlineScheduler}).
 */
abstract sealed class MethodScheduler implements InputSlot.Taker permits OwnThreadScheduler, InlineScheduler {

    /** How a method's own thread is named: then the method id. */
    static final String THREAD_PREFIX = "habla-method-";

    final String id;
    private final List<InputSlot> slots;
    private final EngineClock clock;
    private final WorkCount work;
    private final ConcurrentLinkedQueue<Runnable> turns = new ConcurrentLinkedQueue<>();
    /**
     * How many turns wait in {@link #turns}: counted up after a turn is added, down after one is taken, so that a
     * pass and {@link #nothingWaiting} (every sample, twice for a light method) ask one field, not the queue.
     */
    private final AtomicInteger turnsWaiting = new AtomicInteger();
    private final RateMeter handled = new RateMeter();
    private final LatencyStats latency = new LatencyStats();
    private volatile MethodHost host;
    private LongSupplier motionResets;
    private long motionResetsSeen;

    MethodScheduler(String id, List<InputSlot> slots, EngineClock clock, WorkCount work, MethodHost host) {
        this.id = id;
        this.slots = List.copyOf(slots);
        this.clock = clock;
        this.work = work;
        this.host = host;
    }

    /** Starts the host, then runs the method's messages. */
    abstract void start();

    /** Stops taking messages, waiting at most {@code waitMillis} for the one being handled, then stops the host. */
    abstract void stop(long waitMillis);

    /** A slot has a sample, or a turn is waiting: see that it is handled. From any thread. */
    @Override
    public abstract void wake();

    /** Adds what the status says of how the method's messages are run. */
    abstract void threadStatusTo(ObjectNode status);

    /** Where the method runs now. */
    final MethodHost host() {
        return host;
    }

    /** Moves the method to another host; before {@link #start}, or from a turn. */
    final void host(MethodHost to) {
        this.host = to;
    }

    /** Has the method hear of motion resets ({@link MotionWatchdog}); before {@link #start}. */
    final void followMotionResets(LongSupplier resets) {
        this.motionResets = resets;
        this.motionResetsSeen = resets.getAsLong();
    }

    /** Adds a turn for the method and wakes it; counted as work until it has run. */
    final void turn(Runnable turn) {
        work.begin();
        turns.add(turn);
        turnsWaiting.incrementAndGet(); // a full fence before wake reads whether the method is held
        wake();
    }

    /** Adds how much the method handled, how fast, and how late, to its status. */
    final void statusTo(ObjectNode status, long nowMicros) {
        status.put("handled", handled.total());
        status.put("handledPerS", handled.perSecond(nowMicros));
        status.set("latency", latency.snapshot());
        threadStatusTo(status);
    }

    /** Whether no sample and no turn waits. */
    final boolean nothingWaiting() {
        for (InputSlot slot : slots) {
            if (!slot.isEmpty()) {
                return false;
            }
        }
        return turnsWaiting.get() == 0;
    }

    /**
     * One pass: at most one sample from every input (round robin), then the turns waiting now. Only one thread at a
     * time may run a pass.
     *
     * @return whether anything was handled
     */
    final boolean drainOnce() {
        boolean worked = false;
        for (InputSlot slot : slots) {
            Sample s = slot.poll();
            if (s != null) {
                worked = true;
                handle(slot, s);
            }
        }
        int waiting = turnsWaiting.get();
        if (waiting == 0) {
            return worked;
        }
        for (int n = waiting; n > 0; n--) {
            Runnable turn = turns.poll();
            if (turn == null) {
                break;
            }
            turnsWaiting.decrementAndGet();
            worked = true;
            catchUpMotionReset();
            try {
                turn.run();
            } finally {
                work.end();
            }
        }
        return worked;
    }

    /** Hands one sample taken from {@code slot} to the method, measured; it was counted in as work. */
    final void handle(InputSlot slot, Sample s) {
        catchUpMotionReset();
        long now = clock.nowMicros();
        latency.record(now - s.sourceMicros());
        handled.mark(now);
        try {
            host.deliver(slot.input(), s);
        } finally {
            work.end();
        }
    }

    /**
     * Tells the method of a motion reset it has not heard of yet. Read after the message was taken, so a message
     * that came after a reset (a value written once control is back) always finds the reset told first.
     */
    private void catchUpMotionReset() {
        LongSupplier resets = motionResets;
        if (resets == null) {
            return;
        }
        long now = resets.getAsLong();
        if (now != motionResetsSeen) {
            motionResetsSeen = now;
            host.motionStopped();
        }
    }
}
