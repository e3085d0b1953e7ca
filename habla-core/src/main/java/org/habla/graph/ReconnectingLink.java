package org.habla.graph;

import java.io.IOException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;
import org.habla.config.Reconnect;

/**
 * The one loop that keeps a connection to a peer alive, whatever is spoken over it: a robot's server
 * ({@link ConnectionLink}), a client library's transport ({@link ClientLink}) or a worker ({@link RemotePlacement}).
 * Each attempt gets a fresh {@link Session}, which holds the protocol; the loop owns the rest:
 *
 * <pre>
 *   session = sessions.get()
 *   open() ──ok──▶ log, mark up ──▶ readNext() … readNext() ──IOException──▶ mark down, close() ──▶ back-off ──▶ next
 *     └──IOException (log the outage, count it)────────────────────▶ mark down, close() ──▶ back-off ──▶ next
 * </pre>
 *
 * <ul>
 *   <li>Its thread, the running flag, and the counts the status shows: {@code connects}, {@code failures},
 *       {@code lastError} (cleared once a session is up).</li>
 *   <li>The wait between attempts ({@link BackOff}): it starts again from the shortest once a session has been
 *       up. The outage log ({@link OutageLog}, made by the owner with its own logger and name).</li>
 *   <li>{@link #stop}: no more attempts; a session that is up says goodbye (the thread keeps it up and open until
 *       then, even if a reading ended its read loop as the stop began); the connection is closed, a back-off
 *       wait ends at once, and the thread is given two seconds to end.</li>
 * </ul>
 *
 * A failure while the link is being stopped is not counted nor logged: it is the stop closing the connection.
 *
 * @param <S> the owner's session type, so the owner can write through the session that is up
 */
final class ReconnectingLink<S extends ReconnectingLink.Session> {

    /** How long {@link #stop} waits for the link's thread to end. */
    static final long STOP_JOIN_MILLIS = 2_000;

    /**
     * The protocol spoken over one connection, for one attempt: opened once, read until it fails, closed once.
     * {@link #open} and {@link #readNext} run on the link's thread.
     */
    interface Session {

        /** Connects and runs the opening exchange; returns once the peer has accepted the session. */
        void open() throws IOException;

        /**
         * Blocks for the next unit of input and handles it. An {@link IOException} says the connection is lost
         * (the peer closed it, went silent for longer than its stream allows, or the connection was closed).
         */
        void readNext() throws IOException;

        /** Says goodbye to the peer; called once by {@link ReconnectingLink#stop} while this session is up. */
        default void goodbye() {
        }

        /**
         * Closes the connection and ends what runs beside it, so that {@link #open} or {@link #readNext} in
         * progress fails. From any thread, more than once, before {@link #open} even; never throws.
         */
        void close();
    }

    /** What the owner of a link does as it comes up and goes down; every method runs on the link's thread. */
    interface StateListener {

        /**
         * Runs {@code flip}, which makes the link up or down, together with whatever must change at the same
         * moment (under the owner's lock, if it has one).
         *
         * @param wasUp whether the link was up before; false when an attempt that never came up ends
         */
        default void flip(boolean nowUp, boolean wasUp, Runnable flip) {
            flip.run();
        }

        /** The link is up and the log has said so; its session is about to be read. */
        default void wentUp() {
        }

        /** An attempt or a session ended and its connection is closed; {@code wasUp} if it had been up. */
        default void wentDown(boolean wasUp) {
        }

        /** A listener that runs {@code onStateChange} after each change, up or down. */
        static StateListener notifying(Runnable onStateChange) {
            return notifying(onStateChange, null);
        }

        /**
         * The same, flipping the link up or down while holding {@code flipLock} (if not null): a write in progress
         * under that lock ends before its session is closed.
         */
        static StateListener notifying(Runnable onStateChange, java.util.concurrent.locks.Lock flipLock) {
            return new StateListener() {
                @Override
                public void flip(boolean nowUp, boolean wasUp, Runnable flip) {
                    if (flipLock == null) {
                        flip.run();
                        return;
                    }
                    flipLock.lock();
                    try {
                        flip.run();
                    } finally {
                        flipLock.unlock();
                    }
                }

                @Override
                public void wentUp() {
                    onStateChange.run();
                }

                @Override
                public void wentDown(boolean wasUp) {
                    if (wasUp) {
                        onStateChange.run();
                    }
                }
            };
        }
    }

    /** How the reader thread of a robot interface's connection is named: then {@code INTERFACE/CONNECTION}. */
    static final String THREAD_PREFIX = "habla-link-";

    private final String threadName;
    private final Supplier<S> sessions;
    private final BackOff backOff;
    private final OutageLog outages;
    private final StateListener listener;
    private final AtomicLong connects = new AtomicLong();
    private final AtomicLong failures = new AtomicLong();
    private volatile boolean running;
    private volatile String lastError = "";
    /** The session of the attempt in progress, up or not: what {@link #stop} closes. */
    private volatile S current;
    /** The session that is up, or null while the link is down. */
    private volatile S live;
    /**
     * Opened by {@link #stop} once its goodbye is said (or there was none to say) and the connection closed: until
     * then, a link thread whose read loop ends because of the stop keeps its session up and open, so the goodbye is
     * written to an open connection even when a reading arrived as the stop began.
     */
    private final CountDownLatch farewell = new CountDownLatch(1);
    private Thread thread;

    /**
     * @param threadName the name of the link's thread ({@code habla-link-robot/arcos})
     * @param sessions a fresh session for each attempt
     * @param outages the outage log, with the owner's logger and its name for the link
     */
    ReconnectingLink(String threadName, Reconnect reconnect, Supplier<S> sessions, OutageLog outages,
            StateListener listener) {
        this.threadName = threadName;
        this.sessions = sessions;
        this.backOff = new BackOff(reconnect);
        this.outages = outages;
        this.listener = listener;
    }

    /**
     * Starts the link's thread: a platform thread, because a daemon has a handful of links and every reading
     * waits on this thread's blocking read — a platform thread is woken by the kernel when bytes arrive, a
     * virtual one only after the JDK's poller has noticed them and handed it to a carrier (two more hand-offs
     * on every sample's way in).
     */
    void start() {
        running = true;
        int realtime = RealtimeThreads.asked();
        thread = Thread.ofPlatform().daemon().name(threadName).start(() -> loop(realtime));
    }

    /** Says goodbye if up, closes the connection and stops reconnecting; waits a bounded time for the thread. */
    void stop() {
        running = false;
        S up = live;
        try {
            if (up != null) {
                up.goodbye();
            }
            S attempt = current;
            if (attempt != null) {
                attempt.close();
            }
        } finally {
            farewell.countDown();
        }
        backOff.wake();
        if (thread != null) {
            try {
                thread.join(STOP_JOIN_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** Whether the link keeps trying: true from {@link #start} until {@link #stop}. */
    boolean running() {
        return running;
    }

    boolean up() {
        return live != null;
    }

    /** The session that is up now, or null while the link is down. */
    S session() {
        return live;
    }

    /** Sessions that came up. */
    long connects() {
        return connects.get();
    }

    /** Attempts that failed and sessions that were lost. */
    long failures() {
        return failures.get();
    }

    /** Why the last attempt or session failed; empty when none did, or once a session is up again. */
    String lastError() {
        return lastError;
    }

    /** The wait chooser of this link (tests and benchmarks observe the waits it chooses). */
    BackOff backOff() {
        return backOff;
    }

    private void loop(int realtimePriority) {
        RealtimeThreads.raiseCurrentTo(realtimePriority);
        while (running) {
            S s = sessions.get();
            current = s;
            Exception failure;
            try {
                if (!running) {
                    break; // stop() came before this attempt was current: it is closed below, never opened
                }
                s.open();
                connects.incrementAndGet();
                lastError = "";
                backOff.reset();
                // Told before it shows: whoever sees the link up (the status, a test waiting for it) finds the line.
                outages.up();
                listener.flip(true, false, () -> live = s);
                listener.wentUp();
                while (running) {
                    s.readNext();
                }
                break;
            } catch (IOException | RuntimeException e) {
                failure = e;
                if (running) {
                    lastError = e.getMessage() == null ? e.toString() : e.getMessage();
                    outages.failed(lastError);
                    failures.incrementAndGet();
                }
            } finally {
                if (!running) {
                    awaitFarewell();
                }
                markDown(s);
            }
            if (running && !backOff.pause(failure, () -> running)) {
                running = false;
            }
        }
    }

    /** Waits (bounded) until {@link #stop} has said goodbye through the session this thread holds, and closed it. */
    private void awaitFarewell() {
        try {
            farewell.await(STOP_JOIN_MILLIS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void markDown(S s) {
        boolean was = live != null;
        listener.flip(false, was, () -> live = null);
        s.close();
        listener.wentDown(was);
    }
}
