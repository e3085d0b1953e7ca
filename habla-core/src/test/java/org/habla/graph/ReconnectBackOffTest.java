package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.net.Expose;
import org.habla.config.Fallback;
import org.habla.config.HablaConfig;
import org.habla.config.InterfaceConfig;
import org.habla.net.Limits;
import org.habla.config.MethodConfig;
import org.habla.config.Reconnect;
import org.habla.config.Safety;
import org.habla.config.Source;
import org.habla.config.StatusConfig;
import org.habla.driver.InterfaceAddress;
import org.habla.method.Layer;
import org.habla.plugin.NoParams;
import org.habla.testing.LogLines;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The waits a link chooses between connection attempts, read as the link chooses them (not timed): they double
 * while a peer fails its handshake, stay at the shortest while nothing listens, and start again at the shortest
 * once a session has been up — for a robot's connection and for a worker's.
 */
@Timeout(60)
class ReconnectBackOffTest {

    private static final Reconnect FAST = new Reconnect(40, 320, 2_000, 5_000);
    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
    }

    @Test
    void aRobotLinkThatWasUpWaitsTheShortestTimeAfterItDropsHoweverLongTheWaitsHadGrown() throws Exception {
        Peer robot = peer("ready", "busy");
        MethodGraph g = robotGraph(robot.port());
        BlockingQueue<Long> waits = observe(((ConnectionLink) g.interfaceLink("robot").connections().get(0)).backOff());
        g.start();
        assertThat(take(waits, 5)).as("a failed handshake doubles the wait up to maxMs")
                .containsExactly(40L, 80L, 160L, 320L, 320L);
        robot.accept = true;
        await(() -> g.status().path("interfaces").get(0).path("up").asBoolean(), "the link is up");
        waits.clear();
        robot.dropClient();
        assertThat(take(waits, 1)).as("the first wait after a session was up").containsExactly(40L);
    }

    @Test
    void aRobotWhoseServerDoesNotListenYetIsTriedAgainAfterTheShortestWait() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        try (LogLines log = new LogLines(ConnectionLink.class)) {
            MethodGraph g = robotGraph(port);
            BlockingQueue<Long> waits = observe(((ConnectionLink) g.interfaceLink("robot").connections().get(0)).backOff());
            g.start();
            assertThat(take(waits, 5)).as("a refused connect is an answer: try again soon")
                    .containsExactly(40L, 40L, 40L, 40L, 40L);
            take(waits, 5);
            assertThat(log.at(Level.WARN)).as("ten failed attempts, one warning").hasSize(1).first().asString()
                    .startsWith("link robot/main (127.0.0.1:" + port + ") down: Connection refused");
        }
    }

    @Test
    void aWorkerLinkThatWasUpWaitsTheShortestTimeAfterItDrops() throws Exception {
        Peer worker = workerPeer();
        MethodConfig in = new MethodConfig("in", "command-virtual", Layer.VIRTUAL, Map.of("in", new Source.Control()),
                Map.of(), new NoParams(), Optional.of(new Expose("in", "127.0.0.1", 7001)), Optional.empty());
        MethodConfig p = new MethodConfig("p", "add-one-processing", Layer.PROCESSING,
                Map.of("in", new Source.MethodOutput("in", "out")), Map.of(), new NoParams(), Optional.empty(),
                Optional.of("127.0.0.1:" + worker.port()), Fallback.NONE);
        MethodGraph g = graph(new HablaConfig("backoff-test", Limits.DEFAULTS, new Safety(0),
                new StatusConfig("127.0.0.1", 0), List.of(), List.of(in, p)));
        BlockingQueue<Long> waits = observe(g.placement("p").backOff());
        g.start();
        long initial = Reconnect.DEFAULTS.initialMs();
        assertThat(take(waits, 3)).as("a worker that will not place the method: the wait doubles")
                .containsExactly(initial, 2 * initial, 4 * initial);
        worker.accept = true;
        await(() -> g.placement("p").up(), "the placement is up");
        waits.clear();
        worker.dropClient();
        assertThat(take(waits, 1)).as("the first wait after the worker was up").containsExactly(initial);
    }

    // ------------------------------------------------------------------ set-up

    private MethodGraph robotGraph(int port) {
        MethodConfig s = new MethodConfig("s", "add-one-sensor", Layer.SENSORS_ACTUATORS,
                Map.of("in", new Source.Channel("robot", "value")), Map.of(), new NoParams(), Optional.empty(),
                Optional.empty());
        InterfaceConfig robot = new InterfaceConfig("robot", "lines-test",
                new InterfaceAddress("127.0.0.1", OptionalInt.of(port)), new NoParams(), FAST);
        return graph(new HablaConfig("backoff-test", Limits.DEFAULTS, new Safety(0), new StatusConfig("127.0.0.1", 0),
                List.of(robot), List.of(s)));
    }

    private MethodGraph graph(HablaConfig config) {
        MethodGraph g = MethodGraph.build(config, TestMethods.registry(), EngineClock.system());
        toClose.add(g);
        return g;
    }

    private static BlockingQueue<Long> observe(BackOff backOff) {
        BlockingQueue<Long> waits = new LinkedBlockingQueue<>();
        backOff.observe(waits::add);
        return waits;
    }

    /** The next {@code n} waits the link chooses (each within 10 s). */
    private static List<Long> take(BlockingQueue<Long> waits, int n) throws InterruptedException {
        List<Long> got = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Long w = waits.poll(10, TimeUnit.SECONDS);
            assertThat(w).as("wait %d of %d chosen (so far %s)", i + 1, n, got).isNotNull();
            got.add(w);
        }
        return got;
    }

    private static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
        while (!condition.getAsBoolean()) {
            assertThat(System.nanoTime()).as("waiting until " + what).isLessThan(end);
            Thread.sleep(10);
        }
    }

    /** A robot of {@link LineDriver}'s protocol that answers the handshake with {@code no} until told to accept. */
    private Peer peer(String yes, String no) throws IOException {
        Peer p = new Peer((in, out, accept) -> {
            if (!"hello".equals(in.readLine())) {
                return false;
            }
            out.write(((accept ? yes : no) + "\n").getBytes(StandardCharsets.UTF_8));
            out.flush();
            return accept;
        });
        toClose.add(p);
        return p;
    }

    /** A worker that says hello and refuses to place the method until told to accept. */
    private Peer workerPeer() throws IOException {
        Peer p = new Peer((in, out, accept) -> {
            out.write("{\"type\":\"hello\",\"protocol\":\"habla-worker/1\",\"types\":[\"add-one-processing\"]}\n"
                    .getBytes(StandardCharsets.UTF_8));
            out.flush();
            if (in.readLine() == null) {
                return false;
            }
            out.write((accept ? "{\"type\":\"placed\",\"method\":\"p\",\"inputs\":[\"in\"],\"outputs\":[\"out\"]}\n"
                    : "{\"type\":\"error\",\"code\":\"not_now\",\"message\":\"not now\"}\n")
                    .getBytes(StandardCharsets.UTF_8));
            out.flush();
            return accept;
        });
        toClose.add(p);
        return p;
    }

    /** A peer on loopback that runs an opening exchange per connection and keeps the connection it accepted. */
    private static final class Peer implements AutoCloseable {
        interface Opening {
            boolean run(BufferedReader in, java.io.OutputStream out, boolean accept) throws IOException;
        }

        private final ServerSocket server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        private final BlockingQueue<Socket> kept = new LinkedBlockingQueue<>();
        private final Thread acceptor;
        volatile boolean accept;

        Peer(Opening opening) throws IOException {
            acceptor = Thread.ofVirtual().start(() -> {
                while (!server.isClosed()) {
                    try {
                        Socket s = server.accept();
                        BufferedReader in = new BufferedReader(new InputStreamReader(s.getInputStream(),
                                StandardCharsets.UTF_8));
                        if (opening.run(in, s.getOutputStream(), accept)) {
                            kept.add(s);
                        } else {
                            s.close();
                        }
                    } catch (IOException e) {
                        // closed, or a connection that went away during its opening
                    }
                }
            });
        }

        int port() {
            return server.getLocalPort();
        }

        /** Closes the connection the peer accepted last (waits up to 10 s for one). */
        void dropClient() throws Exception {
            Socket s = kept.poll(10, TimeUnit.SECONDS);
            assertThat(s).as("a connection the peer accepted").isNotNull();
            s.close();
        }

        @Override
        public void close() throws Exception {
            server.close();
            for (Socket s : kept) {
                s.close();
            }
            acceptor.join(2_000);
        }
    }
}
