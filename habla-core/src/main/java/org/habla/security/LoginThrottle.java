package org.habla.security;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.LongSupplier;

/**
 * How many failed logins each source address may make: {@link #BURST} at once, then one every
 * {@link #REFILL_MS}, over every port that shares the throttle (a daemon's sockets and status endpoint share one).
 * An attempt takes a try before its credentials are checked and a successful one gives it back, so only failures
 * count, and an address out of tries is refused without a check. Thread-safe.
 *
 * <pre>
 *   tries of one address:  BURST ----fail----fail----...----&gt; 0  (refused: auth_throttled, not checked)
 *                                \___ one back every REFILL_MS, up to BURST ___/
 * </pre>
 *
 * The addresses it remembers are at most {@link #MAX_ADDRESSES}; the one seen least recently is forgotten first (it
 * starts again with a full burst). Kept as one time per address: when its tries are all back (the generic cell rate
 * algorithm).
 */
public final class LoginThrottle {

    /** Failed logins an address may make at once. */
    public static final int BURST = 10;
    /** One more failed login an address may make after each this many milliseconds. */
    public static final long REFILL_MS = 1_000;
    /** Addresses remembered at most. */
    public static final int MAX_ADDRESSES = 4_096;

    private static final long REFILL_NANOS = REFILL_MS * 1_000_000;

    private final LongSupplier nanoTime;
    /** Per address: when all its tries are back ({@link System#nanoTime()}); least recently seen first. */
    private final Map<String, Long> fullAt = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Long> eldest) {
            return size() > MAX_ADDRESSES;
        }
    };

    public LoginThrottle() {
        this(System::nanoTime);
    }

    /** A throttle on another clock (tests step it). */
    public LoginThrottle(LongSupplier nanoTime) {
        this.nanoTime = nanoTime;
    }

    /**
     * Takes one of {@code host}'s tries for an attempt about to be checked.
     *
     * @return 0 when taken; otherwise how many milliseconds until the next try is back (at least 1)
     */
    public synchronized long take(String host) {
        long now = nanoTime.getAsLong();
        long full = Math.max(fullAt.getOrDefault(host, now), now);
        long overNanos = full + REFILL_NANOS - now - BURST * REFILL_NANOS;
        if (overNanos > 0) {
            return Math.max(1, overNanos / 1_000_000);
        }
        fullAt.put(host, full + REFILL_NANOS);
        return 0;
    }

    /** Gives back the try an attempt of {@code host} took: it succeeded. */
    public synchronized void giveBack(String host) {
        fullAt.computeIfPresent(host, (h, full) -> full - REFILL_NANOS);
    }
}
