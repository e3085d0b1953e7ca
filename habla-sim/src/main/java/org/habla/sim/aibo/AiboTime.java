package org.habla.sim.aibo;

import org.habla.sim.world.SimClock;

/**
 * The simulation's clock as the Aibo's servers use it: milliseconds of simulated time since boot, and
 * waiting for a simulated instant. Every period of the robot (the 32 ms sensor frame, the microphone
 * buffer, the camera frame, the walk's 3 s dead-man time-out) is counted in this time, so a faster clock
 * makes the whole robot faster and changes nothing else.
 */
public final class AiboTime {

    /** How long one wait may take in real time before it is retried (the clock may be stepped by hand). */
    private static final long WAIT_SLICE_MS = 1_000;

    private final SimClock clock;

    public AiboTime(SimClock clock) {
        this.clock = clock;
    }

    /** Simulated milliseconds since boot. */
    public long nowMs() {
        return Math.round(clock.nowS() * 1000);
    }

    /** Simulated seconds since boot. */
    public double nowS() {
        return clock.nowS();
    }

    /** Waits until simulated time reaches {@code simMs}; returns at once if it has already. */
    public void sleepUntil(long simMs) throws InterruptedException {
        while (!clock.awaitSimTime(simMs / 1000.0, WAIT_SLICE_MS)) {
            // a stopped clock answers at once: do not spin while the servers close
            Thread.sleep(10);
        }
    }
}
