package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.config.Reconnect;
import org.habla.testing.LogLines;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.slf4j.LoggerFactory;

/**
 * The reconnect cycle on its own, with a scripted session in memory: what it counts, the waits it chooses (read as
 * it chooses them, with the counts at that moment), what it tells its owner, and how it stops.
 */
@Timeout(60)
class ReconnectingLinkTest {

    /** The bound of every wait for something that must happen. */
    private static final long WAIT_MS = 15_000;
    private static final Reconnect FAST = new Reconnect(40, 160, 2_000, 0);

    /** What the next attempts do, in order: {@code "up"} opens; an empty script fails with "no answer". */
    private final BlockingQueue<String> script = new LinkedBlockingQueue<>();
    /** What the owner and the peer were told: up, down, goodbye, close. */
    private final BlockingQueue<String> events = new LinkedBlockingQueue<>();
    /** Each wait as it is chosen, with the link's failures and last error at that moment. */
    private final BlockingQueue<String> waits = new LinkedBlockingQueue<>();
    private final BlockingQueue<Thread> linkThreads = new LinkedBlockingQueue<>();
    private ReconnectingLink<FakeSession> link;

    @AfterEach
    void stopLink() {
        if (link != null) {
            link.stop();
        }
    }

    private ReconnectingLink<FakeSession> link(Reconnect reconnect) {
        link = new ReconnectingLink<>("habla-link-test", reconnect, FakeSession::new,
                new OutageLog(LoggerFactory.getLogger(ReconnectingLinkTest.class), "test link"),
                new ReconnectingLink.StateListener() {
                    @Override
                    public void wentUp() {
                        events.add("up");
                    }

                    @Override
                    public void wentDown(boolean wasUp) {
                        events.add(wasUp ? "down after up" : "down, never up");
                    }
                });
        ReconnectingLink<FakeSession> l = link;
        l.backOff().observe(ms -> waits.add(ms + " ms after " + l.failures() + " failures: " + l.lastError()));
        return l;
    }

    @Test
    void anAttemptThatFailsIsCountedLoggedOnceAndWaitedForLongerEachTime() throws Exception {
        try (LogLines log = new LogLines(ReconnectingLinkTest.class)) {
            ReconnectingLink<FakeSession> l = link(FAST);
            l.start();
            assertThat(take(waits, 4)).containsExactly("40 ms after 1 failures: no answer",
                    "80 ms after 2 failures: no answer", "160 ms after 3 failures: no answer",
                    "160 ms after 4 failures: no answer");
            assertThat(l.up()).isFalse();
            assertThat(l.connects()).isZero();
            assertThat(take(events, 8)).as("each attempt is closed, then its owner told").containsExactly(
                    "close", "down, never up", "close", "down, never up", "close", "down, never up",
                    "close", "down, never up");
            assertThat(log.at(Level.WARN)).as("four failed attempts, one warning")
                    .containsExactly("test link down: no answer");
        }
    }

    @Test
    void aSessionThatWasUpIsFollowedByTheShortestWaitHoweverLongTheWaitsHadGrown() throws Exception {
        ReconnectingLink<FakeSession> l = link(FAST);
        l.start();
        assertThat(take(waits, 3)).containsExactly("40 ms after 1 failures: no answer",
                "80 ms after 2 failures: no answer", "160 ms after 3 failures: no answer");
        script.add("up");
        await(l::up, "the link is up");
        assertThat(l.connects()).isEqualTo(1);
        assertThat(l.lastError()).as("cleared once a session is up").isEmpty();
        long failed = l.failures();
        waits.clear();
        l.session().drop("the peer closed the connection");
        assertThat(take(waits, 1)).containsExactly("40 ms after " + (failed + 1)
                + " failures: the peer closed the connection");
        assertThat(l.up()).isFalse();
        assertThat(l.session()).isNull();
        List<String> told = new ArrayList<>();
        events.drainTo(told);
        assertThat(told).containsSubsequence("up", "close", "down after up");
    }

    @Test
    void stopDuringAWaitEndsTheWaitAndTheLinkThread() throws Exception {
        ReconnectingLink<FakeSession> l = link(new Reconnect(60_000, 60_000, 2_000, 0));
        l.start();
        Thread thread = linkThreads.poll(WAIT_MS, TimeUnit.MILLISECONDS);
        assertThat(take(waits, 1)).containsExactly("60000 ms after 1 failures: no answer");
        l.stop();
        assertThat(thread.isAlive()).as("the link's thread ended within stop(), a minute's wait or not").isFalse();
        assertThat(l.running()).isFalse();
        assertThat(linkThreads).as("no attempt after the stop").isEmpty();
    }

    @Test
    void stopWhileUpSaysGoodbyeClosesAndCountsNoFailure() throws Exception {
        try (LogLines log = new LogLines(ReconnectingLinkTest.class)) {
            script.add("up");
            ReconnectingLink<FakeSession> l = link(FAST);
            l.start();
            assertThat(take(events, 1)).containsExactly("up");
            assertThat(l.up()).isTrue();
            Thread thread = linkThreads.poll(WAIT_MS, TimeUnit.MILLISECONDS);
            l.stop();
            assertThat(thread.isAlive()).as("the link's thread ended within stop()").isFalse();
            List<String> told = new ArrayList<>();
            events.drainTo(told);
            assertThat(told).startsWith("goodbye", "close").endsWith("down after up");
            assertThat(l.failures()).isZero();
            assertThat(l.lastError()).isEmpty();
            assertThat(waits).as("no wait chosen after a stop").isEmpty();
            assertThat(log.at(Level.WARN)).as("a stop is not an outage").isEmpty();
        }
    }

    /**
     * A chatty peer: a reading arrives just as the stop begins, so the link's thread leaves its read loop at the
     * same moment as {@link ReconnectingLink#stop} says goodbye through the session. The session stays up and
     * open until the goodbye is said; without that, the thread closed it under the goodbye (or took it down
     * before the stop found it), and a robot that keeps sending missed the goodbye in about one shutdown in
     * five under load. Twenty stops, each with its own link.
     */
    @Test
    void aReadingThatArrivesAsTheStopBeginsDoesNotCostTheGoodbye() throws Exception {
        for (int i = 0; i < 20; i++) {
            events.clear();
            script.add("chatty");
            ReconnectingLink<FakeSession> l = link(FAST);
            l.start();
            assertThat(take(events, 1)).containsExactly("up");
            l.stop();
            List<String> told = new ArrayList<>();
            events.drainTo(told);
            assertThat(told).as("stop %d", i + 1).startsWith("goodbye", "close").endsWith("down after up");
            link = null;
        }
    }

    // ------------------------------------------------------------------ set-up

    /** A session in memory: opens if the script says so, then reads until it is dropped or closed. */
    private final class FakeSession implements ReconnectingLink.Session {

        private final BlockingQueue<String> input = new LinkedBlockingQueue<>();
        private boolean chatty;

        @Override
        public void open() throws IOException {
            linkThreads.add(Thread.currentThread());
            String next = script.poll();
            chatty = "chatty".equals(next);
            if (!"up".equals(next) && !chatty) {
                throw new IOException("no answer");
            }
        }

        /** Blocks until the peer ends the session; a chatty peer's reading comes as soon as the stop begins. */
        @Override
        public void readNext() throws IOException {
            if (chatty) {
                long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
                while (link.running() && System.nanoTime() < end) {
                    Thread.onSpinWait();
                }
                return;
            }
            String end;
            try {
                end = input.poll(WAIT_MS, TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted");
            }
            throw new IOException(end == null ? "the test peer stayed silent too long" : end);
        }

        /** The peer ends the session with {@code why}. */
        void drop(String why) {
            input.add(why);
        }

        /** A chatty peer's goodbye takes a while to write, as one to a robot over TCP does. */
        @Override
        public void goodbye() {
            if (chatty) {
                try {
                    Thread.sleep(20);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
            events.add("goodbye");
        }

        @Override
        public void close() {
            events.add("close");
            input.add("closed");
        }
    }

    /** The next {@code n} elements (each within the bound). */
    private static List<String> take(BlockingQueue<String> queue, int n) throws InterruptedException {
        List<String> got = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            String s = queue.poll(WAIT_MS, TimeUnit.MILLISECONDS);
            assertThat(s).as("element %d of %d (so far %s)", i + 1, n, got).isNotNull();
            got.add(s);
        }
        return got;
    }

    private static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
        while (!condition.getAsBoolean()) {
            assertThat(System.nanoTime()).as("waiting until " + what).isLessThan(end);
            Thread.sleep(10);
        }
    }
}
