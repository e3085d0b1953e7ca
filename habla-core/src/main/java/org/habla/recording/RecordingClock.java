package org.habla.recording;

import java.util.concurrent.atomic.AtomicInteger;
import org.habla.graph.EngineClock;

/**
 * The engine's clock with every run of its periodic work written into the recording. Method ticks (a
 * method that emits at a steady rate), link heartbeats and the watchdog check run when the clock says, not
 * when a reading comes; recording when each ran lets a replay run it between the same two readings.
 */
public final class RecordingClock implements EngineClock {

    private final EngineClock clock;
    private final Recorder recorder;
    private final AtomicInteger registered = new AtomicInteger();

    public RecordingClock(EngineClock clock, Recorder recorder) {
        this.clock = clock;
        this.recorder = recorder;
    }

    @Override
    public long nowMicros() {
        return clock.nowMicros();
    }

    @Override
    public AutoCloseable every(long periodMicros, Runnable task) {
        int index = registered.getAndIncrement();
        return clock.every(periodMicros, () -> {
            recorder.tick(index, clock.nowMicros());
            task.run();
        });
    }

    @Override
    public void close() {
        clock.close();
    }
}
