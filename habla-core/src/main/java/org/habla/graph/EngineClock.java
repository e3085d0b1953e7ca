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
}
