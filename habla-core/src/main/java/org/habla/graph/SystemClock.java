package org.habla.graph;

import java.time.Instant;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Wall-clock time and a single daemon scheduler thread for periodic work. */
final class SystemClock implements EngineClock {

    private static final Logger LOG = LoggerFactory.getLogger(SystemClock.class);

    private final ScheduledExecutorService scheduler = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "habla-clock");
        t.setDaemon(true);
        return t;
    });

    @Override
    public long nowMicros() {
        Instant now = Instant.now();
        return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000;
    }

    @Override
    public AutoCloseable every(long periodMicros, Runnable task) {
        ScheduledFuture<?> f = scheduler.scheduleAtFixedRate(() -> {
            try {
                task.run();
            } catch (RuntimeException e) {
                LOG.error("periodic task failed: {}", e.toString(), e);
            }
        }, periodMicros, periodMicros, TimeUnit.MICROSECONDS);
        return () -> f.cancel(false);
    }

    @Override
    public void close() {
        scheduler.shutdownNow();
    }
}
