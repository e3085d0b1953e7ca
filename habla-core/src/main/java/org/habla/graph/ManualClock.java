package org.habla.graph;

import java.util.ArrayList;
import java.util.List;

/**
 * A clock that moves only when a test says so: {@link #advanceMicros} runs every periodic task that
 * falls due on the way, in time order, on the caller's thread.
 */
public final class ManualClock implements EngineClock {

    private final List<Periodic> tasks = new ArrayList<>();
    /** Written under the clock's lock, read without it (every message an engine thread takes reads it). */
    private volatile long now;

    public ManualClock(long startMicros) {
        this.now = startMicros;
    }

    @Override
    public long nowMicros() {
        return now;
    }

    @Override
    public synchronized AutoCloseable every(long periodMicros, Runnable task) {
        if (periodMicros <= 0) {
            throw new IllegalArgumentException("period must be positive");
        }
        Periodic p = new Periodic(periodMicros, task, now + periodMicros);
        tasks.add(p);
        return () -> {
            synchronized (ManualClock.this) {
                tasks.remove(p);
            }
        };
    }

    /** Moves time forward by {@code micros}, running due tasks in order. */
    public void advanceMicros(long micros) {
        long target;
        synchronized (this) {
            target = now + micros;
        }
        while (true) {
            Periodic next;
            synchronized (this) {
                next = tasks.stream().filter(p -> p.due <= target)
                        .min((a, b) -> Long.compare(a.due, b.due)).orElse(null);
                if (next == null) {
                    now = target;
                    return;
                }
                now = next.due;
                next.due += next.period;
            }
            next.task.run();
        }
    }

    public void advanceMillis(long millis) {
        advanceMicros(millis * 1_000);
    }

    @Override
    public void close() {
        synchronized (this) {
            tasks.clear();
        }
    }

    private static final class Periodic {
        final long period;
        final Runnable task;
        long due;

        Periodic(long period, Runnable task, long due) {
            this.period = period;
            this.task = task;
            this.due = due;
        }
    }
}
