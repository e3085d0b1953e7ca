package org.habla.graph;

import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import org.slf4j.Logger;

/**
 * What a link that keeps reconnecting says in the log: the first failure of an outage as one WARN line, then
 * — while it stays down — one summary line every {@link #SUMMARY_MILLIS} (the attempts made and the last
 * error), and one INFO line when it is up again with how long it was down. Two links missing for a day write
 * a few dozen lines, not one per attempt. Every attempt is still logged at DEBUG.
 *
 * <p>Used from the link's own thread only.
 */
final class OutageLog {

    /** How often a link that stays down says so again. */
    static final long SUMMARY_MILLIS = 60_000;

    private final Logger log;
    private final String what;
    private final LongSupplier nanoTime;
    private boolean down;
    private long downSinceNanos;
    private long lastSummaryNanos;
    private long attempts;
    private String lastError = "";

    /** @param what the link as the log names it, e.g. {@code "link robot/arcos (127.0.0.1:8101)"} */
    OutageLog(Logger log, String what) {
        this(log, what, System::nanoTime);
    }

    /** With a clock of the caller's ({@link System#nanoTime} by default), so a test can step time. */
    OutageLog(Logger log, String what, LongSupplier nanoTime) {
        this.log = log;
        this.what = what;
        this.nanoTime = nanoTime;
    }

    /** A connection attempt failed, or a session that was up ended, with {@code error}. */
    void failed(String error) {
        long now = nanoTime.getAsLong();
        lastError = error;
        if (!down) {
            down = true;
            downSinceNanos = now;
            lastSummaryNanos = now;
            attempts = 1;
            log.warn("{} down: {}", what, error);
            return;
        }
        attempts++;
        if (now - lastSummaryNanos >= TimeUnit.MILLISECONDS.toNanos(SUMMARY_MILLIS)) {
            lastSummaryNanos = now;
            log.warn("{} still down after {} failed attempts in {} s: {}", what, attempts, seconds(now - downSinceNanos),
                    lastError);
        } else {
            log.debug("{} still down: {}", what, error);
        }
    }

    /** The link is up: ends the outage, if there was one. */
    void up() {
        if (down) {
            log.info("{} up again after {} s down ({} failed attempts)", what, seconds(nanoTime.getAsLong() - downSinceNanos),
                    attempts);
        } else {
            log.info("{} up", what);
        }
        down = false;
    }

    private static String seconds(long nanos) {
        return String.format(java.util.Locale.ROOT, "%.1f", nanos / 1e9);
    }
}
