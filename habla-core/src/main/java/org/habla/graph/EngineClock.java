package org.habla.graph;

/**
 * The engine's source of time and of periodic work. The system clock runs on wall time and a
 * scheduler thread; {@link ManualClock} lets tests step time instead of waiting.
 */
public interface EngineClock {

    /** Microseconds since the epoch. */
    long nowMicros();

    /** Runs {@code task} every {@code periodMicros}, first after one period. Returns a handle that cancels it. */
    AutoCloseable every(long periodMicros, Runnable task);

    /** Stops any thread the clock owns. */
    void close();

    /** The wall clock, with one scheduler thread. */
    static EngineClock system() {
        return new SystemClock();
    }

    /**
     * A clock that runs {@code speed} times faster than the wall clock: periodic work comes that much
     * sooner and time stamps advance that much faster. For a daemon driving a simulated robot whose
     * time is sped up by the same factor; never for a real robot.
     */
    static EngineClock scaled(double speed) {
        return new SystemClock(speed);
    }
}
