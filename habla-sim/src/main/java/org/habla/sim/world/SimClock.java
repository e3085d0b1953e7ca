package org.habla.sim.world;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Sim time and the fixed-step loop that drives everything in a simulation. Sim time advances in steps of
 * {@code stepS} and runs {@code speed}× real time: at speed 10 a 100 ms SIP period takes 10 ms of wall time. Every
 * {@link Stepper} (physics, the teacher, the robot's periodic packets, the audio streams, the ground-truth
 * broadcast) is called once per step, in the order added, on the loop's one thread — so a run is the same whatever
 * the machine's load, only slower. A stepper that throws is logged and the loop goes on.
 *
 * <p>Tests may drive the clock without its thread through {@link #stepOnce()}.
 */
public final class SimClock implements AutoCloseable {

    /** One participant in the simulation's fixed step. */
    @FunctionalInterface
    public interface Stepper {
        /** Called once per step; {@code nowS} is the sim time at the end of the step. Must not block. */
        void step(double nowS, double dtS);
    }

    private static final Logger LOG = LoggerFactory.getLogger(SimClock.class);
    /** When the loop falls this far behind real time it stops trying to catch up (a paused JVM, a busy machine). */
    private static final long MAX_LAG_NS = TimeUnit.MILLISECONDS.toNanos(500);

    private final double speed;
    private final double stepS;
    private final List<Stepper> steppers = new CopyOnWriteArrayList<>();
    private final Object tick = new Object();
    private volatile long steps;
    private volatile boolean closed;
    private Thread loop;

    /**
     * @param speed how many times faster than real time sim time runs (≥ 1)
     * @param stepS the fixed physics step in sim seconds (e.g. 0.01)
     */
    public SimClock(double speed, double stepS) {
        if (!(speed >= 1) || !Double.isFinite(speed)) {
            throw new IllegalArgumentException("speed must be a number ≥ 1, was " + speed);
        }
        if (!(stepS > 0) || stepS > 1) {
            throw new IllegalArgumentException("stepS must be in (0, 1] s, was " + stepS);
        }
        this.speed = speed;
        this.stepS = stepS;
    }

    public double speed() {
        return speed;
    }

    public double stepS() {
        return stepS;
    }

    /** The current sim time in seconds since the clock started. */
    public double nowS() {
        return steps * stepS;
    }

    /** Adds a participant; it runs from the next step on. */
    public void add(Stepper stepper) {
        steppers.add(stepper);
    }

    /** Advances sim time by one step and runs every participant (tests; or the loop thread). */
    public void stepOnce() {
        long n = steps + 1;
        double now = n * stepS;
        for (Stepper s : steppers) {
            try {
                s.step(now, stepS);
            } catch (RuntimeException e) {
                LOG.warn("a simulation step failed at t={}s: {}", now, e.toString(), e);
            }
        }
        steps = n;
        synchronized (tick) {
            tick.notifyAll();
        }
    }

    /** Starts the loop thread that steps sim time in pace with real time × speed. */
    public synchronized void start() {
        if (loop != null) {
            throw new IllegalStateException("the sim clock is already running");
        }
        loop = new Thread(this::run, "sim-clock");
        loop.setDaemon(true);
        loop.start();
    }

    /**
     * Waits (in real time, at most {@code timeoutMs}) until sim time reaches {@code simS}.
     *
     * @return whether it did
     */
    public boolean awaitSimTime(double simS, long timeoutMs) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        synchronized (tick) {
            while (nowS() < simS - 1e-9) {
                long left = deadline - System.nanoTime();
                if (left <= 0 || closed) {
                    return nowS() >= simS - 1e-9;
                }
                TimeUnit.NANOSECONDS.timedWait(tick, left);
            }
        }
        return true;
    }

    /** Real nanoseconds that a span of sim time takes. */
    public long realNanos(double simS) {
        return (long) (simS / speed * 1e9);
    }

    private void run() {
        long stepNs = realNanos(stepS);
        long next = System.nanoTime();
        while (!closed) {
            long now = System.nanoTime();
            if (now < next) {
                try {
                    TimeUnit.NANOSECONDS.sleep(next - now);
                } catch (InterruptedException e) {
                    return;
                }
                continue;
            }
            stepOnce();
            next += stepNs;
            if (System.nanoTime() - next > MAX_LAG_NS) {
                next = System.nanoTime();
            }
        }
    }

    @Override
    public void close() {
        closed = true;
        Thread t;
        synchronized (this) {
            t = loop;
        }
        if (t != null) {
            t.interrupt();
            try {
                t.join(2_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        synchronized (tick) {
            tick.notifyAll();
        }
    }
}
