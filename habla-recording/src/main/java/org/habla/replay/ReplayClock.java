package org.habla.replay;

import java.util.ArrayList;
import java.util.List;
import org.habla.graph.EngineClock;

/**
 * The engine's clock during a replay: it shows the recorded time and moves only when the replay moves it.
 * Periodic work (method ticks, the watchdog) is run by the replay where the recording says it ran; only for
 * a recording without tick records does this clock run it itself, on the replay's thread, when its period
 * comes round ({@link #advanceTo} with {@code scheduled} true).
 */
final class ReplayClock implements EngineClock {

    private final List<Periodic> tasks = new ArrayList<>();
    private long now;

    ReplayClock(long startMicros) {
        this.now = startMicros;
    }

    @Override
    public synchronized long nowMicros() {
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
            synchronized (ReplayClock.this) {
                p.cancelled = true;
            }
        };
    }

    /**
     * Moves time to {@code target} (never backwards); when {@code scheduled}, runs every periodic task due on
     * the way, in time order, with {@code afterEach} after each.
     */
    void advanceTo(long target, boolean scheduled, Runnable afterEach) {
        while (scheduled) {
            Periodic next;
            synchronized (this) {
                next = null;
                for (Periodic p : tasks) {
                    if (!p.cancelled && p.due <= target && (next == null || p.due < next.due)) {
                        next = p;
                    }
                }
                if (next == null) {
                    break;
                }
                now = Math.max(now, next.due);
                next.due += next.period;
            }
            next.task.run();
            afterEach.run();
        }
        synchronized (this) {
            now = Math.max(now, target);
        }
    }

    @Override
    public synchronized void close() {
        tasks.forEach(p -> p.cancelled = true);
    }

    private static final class Periodic {
        final long period;
        final Runnable task;
        long due;
        boolean cancelled;

        Periodic(long period, Runnable task, long due) {
            this.period = period;
            this.task = task;
            this.due = due;
        }
    }
}
