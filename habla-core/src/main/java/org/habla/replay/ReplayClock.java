package org.habla.replay;

import java.util.ArrayList;
import java.util.List;
import org.habla.graph.EngineClock;

/**
 * The engine's clock during a replay: it shows the recorded time and moves only when the replay moves it.
 * Periodic work (method ticks, the watchdog, link heartbeats) is numbered in the order the graph registers
 * it — the same order as in the recorded run — and runs on the replay's thread: where the recording says it
 * ran ({@link #runTask}), or, for a recording without tick records, when its period comes round
 * ({@link #advanceTo} with {@code scheduled} true).
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

    /** Runs periodic task number {@code index} now, as the recording says it ran; false if there is none. */
    boolean runTask(int index) {
        Periodic p;
        synchronized (this) {
            if (index < 0 || index >= tasks.size() || tasks.get(index).cancelled) {
                return false;
            }
            p = tasks.get(index);
        }
        p.task.run();
        return true;
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
