package org.habla.graph;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.LongSupplier;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One method's thread and the order in which it takes its messages: a pass takes at most one sample from every
 * input slot (round robin), then the turns — ticks, background results, a change of placement — that were waiting
 * when the turns began, and hands each to where the method runs ({@link MethodHost}). With nothing to do the
 * thread parks; a producer that adds work wakes it. Before each message the method hears of a motion reset it has
 * not heard of yet.
 */
final class MethodScheduler {

    private static final Logger LOG = LoggerFactory.getLogger(MethodScheduler.class);
    private static final long IDLE_PARK_NANOS = TimeUnit.MILLISECONDS.toNanos(100);
    /** Looks at a claimed, not yet filled queue place before the thread yields its core to the producer. */
    private static final int SPINS_BEFORE_YIELD = 64;
    /** How long a real-time method thread sleeps while a producer fills the place it claimed. */
    private static final long REALTIME_WAIT_NANOS = 20_000;

    private final String id;
    private final List<InputSlot> slots;
    private final EngineClock clock;
    private final WorkCount work;
    private final ConcurrentLinkedQueue<Runnable> turns = new ConcurrentLinkedQueue<>();
    /**
     * Whether the thread is about to park or parked: set before it looks at its slots one last time, so a
     * producer that finds it false knows the thread will see its sample, and unparks only a thread that may
     * sleep (an unpark costs a lock and, for a sleeping thread, a system call).
     */
    private volatile boolean parking;
    private static final VarHandle PARKING;

    static {
        try {
            PARKING = MethodHandles.lookup().findVarHandle(MethodScheduler.class, "parking", boolean.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }
    private final RateMeter handled = new RateMeter();
    private final LatencyStats latency = new LatencyStats();
    private volatile MethodHost host;
    private volatile boolean running;
    private Thread thread;
    private LongSupplier motionResets;
    private long motionResetsSeen;

    MethodScheduler(String id, List<InputSlot> slots, EngineClock clock, WorkCount work, MethodHost host) {
        this.id = id;
        this.slots = List.copyOf(slots);
        this.clock = clock;
        this.work = work;
        this.host = host;
    }

    /** Where the method runs now. */
    MethodHost host() {
        return host;
    }

    /** Moves the method to another host; before {@link #start}, or from a turn. */
    void host(MethodHost to) {
        this.host = to;
    }

    /** Has the method hear of motion resets ({@link MotionWatchdog}); before {@link #start}. */
    void followMotionResets(LongSupplier resets) {
        this.motionResets = resets;
        this.motionResetsSeen = resets.getAsLong();
    }

    /** Starts the host, then the thread. */
    void start() {
        running = true;
        int realtime = RealtimeThreads.asked();
        thread = new Thread(() -> loop(realtime), "habla-method-" + id);
        thread.setDaemon(true);
        host.start();
        thread.start();
    }

    /** Stops the thread, waiting at most {@code waitMillis} for the current message, then the host. */
    void stop(long waitMillis) {
        running = false;
        Thread t = thread;
        if (t != null) {
            LockSupport.unpark(t);
            try {
                t.join(waitMillis);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            if (t.isAlive()) {
                LOG.warn("method {} is still busy after {} ms; stopping it anyway", id, waitMillis);
            }
        }
        host.stop();
    }

    /** Adds a turn for the method's thread and wakes it; counted as work until it has run. */
    void turn(Runnable turn) {
        work.begin();
        turns.add(turn);
        wake();
    }

    /** Wakes the thread: a slot has a sample, or a turn is waiting. */
    void wake() {
        // The first producer to find the thread going to sleep wakes it; the ones after it, while the thread is
        // still being scheduled, find the flag cleared and leave it (each unpark takes the thread's lock).
        if (parking && PARKING.compareAndSet(this, true, false)) {
            Thread t = thread;
            if (t != null) {
                LockSupport.unpark(t);
            }
        }
    }

    /** Adds how much the method handled, how fast, and how late, to its status. */
    void statusTo(ObjectNode status, long nowMicros) {
        status.put("handled", handled.total());
        status.put("handledPerS", handled.perSecond(nowMicros));
        status.set("latency", latency.snapshot());
    }

    private void loop(int realtimePriority) {
        boolean realtime = RealtimeThreads.raiseCurrentTo(realtimePriority);
        int misses = 0;
        while (running) {
            if (drainOnce()) {
                misses = 0;
                continue;
            }
            // Say so before the last look: a sample offered after it finds parking set and unparks us.
            parking = true;
            if (running && nothingWaiting()) {
                LockSupport.parkNanos(this, IDLE_PARK_NANOS);
                misses = 0;
            } else {
                waitForFill(++misses, realtime);
            }
            parking = false;
        }
    }

    /**
     * A producer has claimed a place in a queue and not filled it yet: a few instructions, unless the producer
     * was descheduled in between, and then this thread gives its core away rather than spin for the producer's
     * whole time slice. A real-time thread ({@link RealtimeThreads}) gives it away by sleeping: a yield only
     * hands the core to other real-time threads, never to a normal producer waiting for it.
     */
    private static void waitForFill(int misses, boolean realtime) {
        if (misses < SPINS_BEFORE_YIELD) {
            Thread.onSpinWait();
        } else if (realtime) {
            LockSupport.parkNanos(REALTIME_WAIT_NANOS);
        } else {
            Thread.yield();
        }
    }

    private boolean nothingWaiting() {
        for (InputSlot slot : slots) {
            if (!slot.isEmpty()) {
                return false;
            }
        }
        return turns.isEmpty();
    }

    /** One pass: at most one sample from every input (round robin), then the turns waiting now. */
    private boolean drainOnce() {
        boolean worked = false;
        for (InputSlot slot : slots) {
            Sample s = slot.poll();
            if (s != null) {
                worked = true;
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
        }
        for (int n = turns.size(); n > 0; n--) {
            Runnable turn = turns.poll();
            if (turn == null) {
                break;
            }
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
