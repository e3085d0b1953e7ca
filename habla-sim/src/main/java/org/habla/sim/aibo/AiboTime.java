package org.habla.sim.aibo;

/**
 * The simulator's clock: milliseconds of simulated time since the robot booted, running
 * {@code speed} times faster than the wall clock. Every period of the simulated Aibo (the 32 ms
 * sensor frame, the microphone buffer, the camera frame, the walk's dead-man time-out) is counted in
 * this time, so a faster clock makes the whole robot faster and nothing else changes.
 */
public final class AiboTime {

    private final double speed;
    private final long startNanos = System.nanoTime();

    public AiboTime(double speed) {
        if (!(speed >= 1.0) || Double.isInfinite(speed)) {
            throw new IllegalArgumentException("speed must be a number >= 1, was " + speed);
        }
        this.speed = speed;
    }

    public double speed() {
        return speed;
    }

    /** Simulated milliseconds since boot. */
    public long nowMs() {
        return (long) ((System.nanoTime() - startNanos) * speed / 1e6);
    }

    /** Simulated seconds since boot, with fractions. */
    public double nowS() {
        return (System.nanoTime() - startNanos) * speed / 1e9;
    }

    /** Sleeps until the simulated time reaches {@code simMs}; returns at once if it has already. */
    public void sleepUntil(long simMs) throws InterruptedException {
        long targetNanos = startNanos + (long) (simMs * 1e6 / speed);
        long wait = targetNanos - System.nanoTime();
        if (wait > 0) {
            Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
        }
    }
}
