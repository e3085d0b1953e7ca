package org.habla.graph;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A method on a thread of its own ({@code habla-method-ID}): the thread runs passes while there is work, and parks
 * when there is none; a producer that adds work wakes it. A slow method holds up only its own thread: the operating
 * system schedules the others apart.
 */
final class OwnThreadScheduler extends MethodScheduler {

    private static final Logger LOG = LoggerFactory.getLogger(MethodScheduler.class);
    private static final long IDLE_PARK_NANOS = TimeUnit.MILLISECONDS.toNanos(100);
    /** Looks at a claimed, not yet filled queue place before the thread yields its core to the producer. */
    private static final int SPINS_BEFORE_YIELD = 64;
    /** How long a real-time method thread sleeps while a producer fills the place it claimed. */
    private static final long REALTIME_WAIT_NANOS = 20_000;
    private static final VarHandle PARKING;

    static {
        try {
            PARKING = MethodHandles.lookup().findVarHandle(OwnThreadScheduler.class, "parking", boolean.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    /**
     * Whether the thread is about to park or parked: set before it looks at its slots one last time, so a
     * producer that finds it false knows the thread will see its sample, and unparks only a thread that may
     * sleep (an unpark costs a lock and, for a sleeping thread, a system call).
     */
    private volatile boolean parking;
    private volatile boolean running;
    private final String reason;
    private Thread thread;

    /** @param reason why the method has a thread of its own (the status says it) */
    OwnThreadScheduler(String id, List<InputSlot> slots, EngineClock clock, WorkCount work, MethodHost host,
            String reason) {
        super(id, slots, clock, work, host);
        this.reason = reason;
    }

    @Override
    void start() {
        running = true;
        int realtime = RealtimeThreads.asked();
        thread = new Thread(() -> loop(realtime), THREAD_PREFIX + id);
        thread.setDaemon(true);
        host().start();
        thread.start();
    }

    @Override
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
        host().stop();
    }

    /** Never: a method with a thread of its own takes every sample there. */
    @Override
    public boolean takeNow(InputSlot slot, Sample sample, long arrival) {
        return false;
    }

    @Override
    public void wake() {
        // The first producer to find the thread going to sleep wakes it; the ones after it, while the thread is
        // still being scheduled, find the flag cleared and leave it (each unpark takes the thread's lock).
        if (parking && PARKING.compareAndSet(this, true, false)) {
            Thread t = thread;
            if (t != null) {
                LockSupport.unpark(t);
            }
        }
    }

    @Override
    void threadStatusTo(ObjectNode status) {
        ObjectNode t = status.putObject("thread");
        t.put("name", THREAD_PREFIX + id);
        t.put("inline", false);
        t.put("reason", reason);
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
}
