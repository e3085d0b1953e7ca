package org.habla.graph;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.LongAdder;
import java.util.concurrent.locks.LockSupport;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A light method run by the thread that delivers to it ({@link ThreadPlan}): the delivering thread hands the
 * sample to the method itself, before it goes on with its own work — straight from the offer when the method is
 * free and nothing waits in the slot ({@link #takeNow}), else from the slot once it is in — so a chain of such
 * methods runs as one pass on the producer's thread, in graph order, and nobody is woken. The slots stay as they
 * are: a {@code latest} input still keeps only the newest sample waiting, a {@code queue} input still keeps order
 * and counts what it drops.
 *
 * <p>One message at a time still holds. A thread runs passes only while it holds the method ({@code busy}). A
 * delivery that finds the method held — by the same thread further up its stack (what the method emitted led back
 * to it), or by another thread — leaves its sample in the slot and returns, and the holder takes the sample before
 * it lets go: a holder that lets go looks once more, and runs again if anything waits. A re-entrant delivery thus
 * never runs the method inside itself, and a second delivering thread (the plan admits none, but a driver may
 * surprise it) is served, not raced.
 *
 * <p>Every {@value #TIMED_EVERY}th pass that handles anything is timed in the delivering thread's processor time
 * (what the method and the ones inline after it did, not the time a busy machine took the core away); one that took
 * longer than {@link #OVERRUN_MICROS} µs is counted in the status, and logged once {@link #OVERRUNS_LOGGED} were:
 * a type declared light that takes that long should not be, or the method should get {@code "thread": "own"}.
 */
final class InlineScheduler extends MethodScheduler {

    private static final Logger LOG = LoggerFactory.getLogger(MethodScheduler.class);
    /** How much processor time a pass may take on the delivering thread before it counts as an overrun. */
    static final long OVERRUN_MICROS = 1_000;
    /** One pass in this many is timed (reading a thread's processor time costs more than a light method's work). */
    static final int TIMED_EVERY = 256;
    /** Overruns counted before the first is logged (then one line per thousand): one alone may be a first use. */
    static final int OVERRUNS_LOGGED = 10;
    private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();
    /** How often a thread that let the method go looks again at a queue place claimed and not yet filled. */
    private static final int LOOKS_BEFORE_LEAVING = 64;
    private static final long STOP_POLL_NANOS = TimeUnit.MICROSECONDS.toNanos(100);

    private final AtomicBoolean busy = new AtomicBoolean();
    private volatile boolean running;
    private final String thread;
    private final String reason;
    private final LongAdder overruns = new LongAdder();
    private volatile long longestMicros;
    /** The passes that handled something, so far; the method's holder alone counts them. */
    private long passes;

    /**
     * @param thread the thread the plan says delivers to the method (the status names it)
     * @param reason why the method runs there
     */
    InlineScheduler(String id, List<InputSlot> slots, EngineClock clock, WorkCount work, MethodHost host,
            String thread, String reason) {
        super(id, slots, clock, work, host);
        this.thread = thread;
        this.reason = reason;
    }

    /** Starts the host, then handles what was delivered before, on the starting thread. */
    @Override
    void start() {
        host().start();
        running = true;
        wake();
    }

    @Override
    void stop(long waitMillis) {
        running = false;
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(waitMillis);
        while (!busy.compareAndSet(false, true)) {
            if (System.nanoTime() - end > 0) {
                LOG.warn("method {} is still busy on {} after {} ms; stopping it anyway", id, thread, waitMillis);
                break;
            }
            LockSupport.parkNanos(STOP_POLL_NANOS);
        }
        host().stop();
    }

    /**
     * The sample is handled here and now when the method is free and nothing waits in its slot: the same as
     * queuing it and taking it at once, without the queue. Then whatever came in meanwhile is handled too.
     */
    @Override
    public boolean takeNow(InputSlot slot, Sample sample, long arrival) {
        if (!running || busy.get() || !busy.compareAndSet(false, true)) {
            return false;
        }
        boolean taken = false;
        try {
            if (running && slot.isEmpty()) {
                taken = true;
                long start = timing();
                slot.takenNow(arrival);
                handle(slot, sample);
                passDone(start);
            }
        } finally {
            busy.set(false); // a full fence, as in wake
        }
        if (!nothingWaiting()) {
            wake();
        }
        return taken;
    }

    @Override
    public void wake() {
        int idle = 0;
        while (running && !busy.get() && busy.compareAndSet(false, true)) {
            boolean worked;
            try {
                worked = running && pass();
            } finally {
                // A full fence: what is offered from now on either finds the method free or is seen below.
                busy.set(false);
            }
            if (nothingWaiting()) {
                return;
            }
            // Something came in while this thread let go, or a producer claimed a queue place and is filling it.
            idle = worked ? 0 : idle + 1;
            if (idle >= LOOKS_BEFORE_LEAVING) {
                return; // that producer's own wake, once it has filled the place, finds the method free
            }
            Thread.onSpinWait();
        }
    }

    @Override
    void threadStatusTo(ObjectNode status) {
        ObjectNode t = status.putObject("thread");
        t.put("name", thread);
        t.put("inline", true);
        t.put("reason", reason);
        t.put("overruns", overruns.sum());
        t.put("longestTimedPassCpuUs", longestMicros);
    }

    /** One pass; every {@value #TIMED_EVERY}th that handles anything timed. Runs with the method held. */
    private boolean pass() {
        long start = timing();
        if (!drainOnce()) {
            return false;
        }
        passDone(start);
        return true;
    }

    /** The processor time now if the next pass that handles anything is one to time, else -1. */
    private long timing() {
        return (passes + 1) % TIMED_EVERY == 0 ? CPU.getCurrentThreadCpuTime() : -1;
    }

    /** A pass that handled something, begun at {@code start} ({@link #timing}), is over. */
    private void passDone(long start) {
        passes++;
        if (start < 0) {
            return;
        }
        long micros = TimeUnit.NANOSECONDS.toMicros(CPU.getCurrentThreadCpuTime() - start);
        if (micros > longestMicros) {
            longestMicros = micros;
        }
        if (micros > OVERRUN_MICROS) {
            overruns.increment();
            long n = overruns.sum();
            if (n == OVERRUNS_LOGGED || n % 1_000 == 0) {
                LOG.warn("method {} took {} µs of {}'s processor time with the methods inline after it (limit {} µs;"
                        + " {} of its timed passes did): a light type should take microseconds; give it"
                        + " \"thread\": \"own\" if it cannot", id, micros, thread, OVERRUN_MICROS, n);
            }
        }
    }
}
