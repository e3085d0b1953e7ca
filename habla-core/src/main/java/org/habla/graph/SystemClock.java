package org.habla.graph;

import java.time.Instant;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Wall-clock time and a single daemon scheduler thread for periodic work. With a speed above 1 the
 * clock runs that many times faster than the wall clock (from the moment it was made), for a daemon
 * that drives a simulated robot whose time is sped up the same way.
 */
final class SystemClock implements EngineClock {

    private static final Logger LOG = LoggerFactory.getLogger(SystemClock.class);

    /** Read when the clock is made: its thread starts with the first periodic work, from whichever thread. */
    private final int realtimePriority = RealtimeThreads.asked();
    private final ScheduledExecutorService scheduler = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(() -> {
            RealtimeThreads.raiseCurrentTo(realtimePriority);
            r.run();
        }, "habla-clock");
        t.setDaemon(true);
        return t;
    });

    private final double speed;
    private final long originMicros;
    private final long originNanos;

    SystemClock() {
        this(1.0);
    }

    SystemClock(double speed) {
        if (!(speed >= 1.0) || !Double.isFinite(speed)) {
            throw new IllegalArgumentException("a clock's speed is 1 or more, was " + speed);
        }
        this.speed = speed;
        Instant now = Instant.now();
        this.originMicros = now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000;
        this.originNanos = System.nanoTime();
    }

    @Override
    public long nowMicros() {
        if (speed == 1.0) {
            Instant now = Instant.now();
            return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000;
        }
        return originMicros + (long) ((System.nanoTime() - originNanos) / 1_000.0 * speed);
    }

    @Override
    public AutoCloseable every(long periodMicros, Runnable task) {
        long wallMicros = Math.max(1, (long) (periodMicros / speed));
        ScheduledFuture<?> f = scheduler.scheduleAtFixedRate(() -> {
            try {
                task.run();
            } catch (RuntimeException e) {
                LOG.error("periodic task failed: {}", e.toString(), e);
            }
        }, wallMicros, wallMicros, TimeUnit.MICROSECONDS);
        return () -> f.cancel(false);
    }

    @Override
    public void close() {
        scheduler.shutdownNow();
    }
}
