package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.ConnectException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.habla.bridge.Bridge;
import org.habla.bridge.BridgeSession;
import org.habla.bridge.CommandRole;
import org.habla.config.Reconnect;
import org.habla.net.ControlPoint;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A bridge's connection kept by the engine's reconnecting link, with a scripted bridge in memory: the waits it
 * chooses (doubling while the other side does not answer, the shortest after a refused connect and once a session
 * has been up), the status it adds to the bridge's, and its goodbye on stop.
 */
@Timeout(60)
class BridgeLinkTest {

    private static final long WAIT_MS = 15_000;
    private static final Reconnect FAST = new Reconnect(40, 160, 2_000, 0);

    /** What the next attempts do: "up" opens, "refused" is a refused connect; none left fails with "no answer". */
    private final BlockingQueue<String> script = new LinkedBlockingQueue<>();
    private final BlockingQueue<Long> waits = new LinkedBlockingQueue<>();
    private final List<String> told = new ArrayList<>();
    private final ScriptedBridge bridge = new ScriptedBridge();
    private BridgeLink link;

    @AfterEach
    void stop() {
        if (link != null) {
            link.stop();
        }
    }

    private BridgeLink started() {
        link = new BridgeLink("home", bridge, FAST);
        link.backOff().observe(waits::add);
        link.start();
        return link;
    }

    @Test
    void aBridgeThatWasConnectedWaitsTheShortestTimeAfterItDropsHoweverLongTheWaitsHadGrown() throws Exception {
        BridgeLink l = started();
        assertThat(take(3)).containsExactly(40L, 80L, 160L);
        script.add("up");
        await(l::up);
        assertThat(l.status().path("connects").asLong()).isEqualTo(1);
        assertThat(l.status().path("failures").asLong()).isEqualTo(3);
        assertThat(l.status().has("lastError")).isFalse();
        assertThat(l.status().path("published").asLong()).as("the bridge's own figures").isEqualTo(7);
        waits.clear();
        bridge.drop();
        assertThat(take(1)).containsExactly(40L);
        assertThat(l.status().path("connected").asBoolean()).isFalse();
        assertThat(l.status().path("lastError").asText()).isEqualTo("the broker went away");
    }

    @Test
    void aRefusedConnectIsTriedAgainAfterTheShortestWait() throws Exception {
        started();
        assertThat(take(2)).containsExactly(40L, 80L);
        script.add("refused");
        assertThat(take(1)).containsExactly(40L);
    }

    @Test
    void stopSaysGoodbyeOnTheSessionThatIsUpThenClosesTheBridge() throws Exception {
        script.add("up");
        BridgeLink l = started();
        await(l::up);
        l.stop();
        link = null;
        synchronized (told) {
            assertThat(told).containsSubsequence("goodbye", "session closed", "bridge closed");
        }
    }

    private List<Long> take(int n) throws InterruptedException {
        List<Long> got = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Long w = waits.poll(WAIT_MS, TimeUnit.MILLISECONDS);
            assertThat(w).as("wait %d of %d", i + 1, n).isNotNull();
            got.add(w);
        }
        return got;
    }

    private static void await(java.util.function.BooleanSupplier state) throws InterruptedException {
        long until = System.nanoTime() + WAIT_MS * 1_000_000L;
        while (!state.getAsBoolean()) {
            assertThat(System.nanoTime()).as("the state came within %d ms", WAIT_MS).isLessThan(until);
            Thread.sleep(5);
        }
    }

    private void tell(String what) {
        synchronized (told) {
            told.add(what);
        }
    }

    /** A bridge whose sessions do what the script says. */
    private final class ScriptedBridge implements Bridge {
        private volatile CountDownLatch current = new CountDownLatch(0);

        void drop() {
            current.countDown();
        }

        @Override
        public void start(String system, List<ControlPoint> points, CommandRole role) {
        }

        @Override
        public BridgeSession session() {
            CountDownLatch ended = new CountDownLatch(1);
            return new BridgeSession() {
                @Override
                public void open(Duration timeout) throws IOException {
                    String next = script.poll();
                    if ("refused".equals(next)) {
                        throw new ConnectException("Connection refused");
                    }
                    if (!"up".equals(next)) {
                        throw new IOException("no answer");
                    }
                    current = ended;
                }

                @Override
                public void readNext() throws IOException {
                    try {
                        ended.await();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                    throw new IOException("the broker went away");
                }

                @Override
                public void goodbye() {
                    tell("goodbye");
                }

                @Override
                public void close() {
                    tell("session closed");
                    ended.countDown();
                }
            };
        }

        @Override
        public ObjectNode status() {
            return JsonNodeFactory.instance.objectNode().put("published", 7);
        }

        @Override
        public void close() {
            tell("bridge closed");
        }
    }
}
