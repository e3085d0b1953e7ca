package org.habla.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.HdrHistogram.Histogram;
import org.habla.daemon.Daemon;

/**
 * Benchmark (a): end-to-end latency of one reading through the daemon over loopback, from the moment the
 * robot stamps it to the moment a control client has parsed it, with readings at a fixed rate — the light chains
 * as the engine runs them (on the robot link's reader thread) and with each method on a thread of its own; and the
 * same hops through {@link PlainRelay}, on one thread and with four thread hand-offs (as many as the
 * daemon's path: link reader → three method threads → the client's writer), the latter also with its
 * socket reader and writer on virtual threads as in the daemon, as the floor. The Pioneer's obstacle chain runs
 * the same way with its real payloads: eight sonar ranges in, a range scan and a nearest-obstacle record between
 * the methods. The paths are measured in turn, in rounds ({@link #ROUNDS}), so that each ratio between them is
 * taken over the same stretch of the run.
 */
final class LatencyBench {

    /** How long each daemon path runs before any is measured, in a JVM that has not run it yet. */
    static final int JIT_WARMUP_S = 10;
    /** Into how many rounds the measured time of each path is cut. */
    static final int ROUNDS = 5;
    /** How long a path runs after it opens before a round measures it (the compiler is done by then). */
    static final long SLICE_SETTLE_MS = 1_000;

    private final int rateHz;
    private final int warmupS;
    private final int seconds;

    LatencyBench(int rateHz, int warmupS, int seconds) {
        this.rateHz = rateHz;
        this.warmupS = warmupS;
        this.seconds = seconds;
    }

    void run() throws Exception {
        System.out.printf("%n(a) latency, robot stamp -> control client, %d Hz readings, %d s warm-up, %d s measured%n",
                rateHz, warmupS, seconds);
        System.out.printf("%-44s %8s %8s %8s %8s %8s %8s%n", "path", "samples", "lost", "p50 µs", "p99 µs",
                "p99.9 µs", "max µs");
        PathFactory numbers = robot -> {
            Daemon d = BenchDaemon.start(robot.port());
            return new Path(d.port("value"), d::close);
        };
        PathFactory numbersOwn = robot -> {
            Daemon d = BenchDaemon.startOwnThreads(robot.port());
            return new Path(d.port("value"), d::close);
        };
        PathFactory sonar = robot -> {
            Daemon d = BenchDaemon.startSonarChain(robot.port());
            return new Path(d.port("value"), d::close);
        };
        PathFactory sonarOwn = robot -> {
            Daemon d = BenchDaemon.startSonarChain(robot.port(), true);
            return new Path(d.port("value"), d::close);
        };
        System.out.printf("(JIT warm-up: each daemon path runs %d s unmeasured first, so that no path is measured "
                + "while the compiler still works on the engine's code)%n", JIT_WARMUP_S);
        LatencyBench warmUp = new LatencyBench(rateHz, JIT_WARMUP_S, 0);
        warmUp.quietly(numbers, BenchRobot.Channels.NUMBER);
        warmUp.quietly(numbersOwn, BenchRobot.Channels.NUMBER);
        warmUp.quietly(sonar, BenchRobot.Channels.SONAR);
        warmUp.quietly(sonarOwn, BenchRobot.Channels.SONAR);
        List<Route> routes = List.of(
                new Route("daemon: channel -> pass-through x2", BenchRobot.Channels.NUMBER, numbers),
                new Route("  the same, each method on its own thread", BenchRobot.Channels.NUMBER, numbersOwn),
                new Route("daemon: sonar -> nearest-distance -> relay", BenchRobot.Channels.SONAR, sonar),
                new Route("  the same, each method on its own thread", BenchRobot.Channels.SONAR, sonarOwn),
                new Route("plain relay, 1 thread", BenchRobot.Channels.NUMBER, robot -> {
                    PlainRelay r = new PlainRelay(robot.port(), 0, false);
                    return new Path(r.port(), r::close);
                }),
                new Route("plain relay, 4 thread hand-offs", BenchRobot.Channels.NUMBER, robot -> {
                    PlainRelay r = new PlainRelay(robot.port(), 4, false);
                    return new Path(r.port(), r::close);
                }),
                new Route("plain relay, 4 hand-offs, virtual-thread I/O", BenchRobot.Channels.NUMBER, robot -> {
                    PlainRelay r = new PlainRelay(robot.port(), 4, true);
                    return new Path(r.port(), r::close);
                }));
        List<Figures> f = inRounds(routes);
        Figures relay1 = f.get(4);
        Figures relay4 = f.get(5);
        System.out.println("  ratios to the plain relay on 1 thread (p50 / p99), and to the one with 4 hand-offs:");
        ratios("daemon: channel -> pass-through x2", f.get(0), relay1, relay4);
        ratios("  the same, own threads", f.get(1), relay1, relay4);
        ratios("daemon: sonar -> nearest-distance -> relay", f.get(2), relay1, relay4);
        ratios("  the same, own threads", f.get(3), relay1, relay4);
    }

    /** A path measured among others: its name, what its robot sends and how it is opened. */
    record Route(String name, BenchRobot.Channels channels, PathFactory factory) {
    }

    /**
     * Measures every route in {@link #ROUNDS} rounds of {@code seconds / ROUNDS} each, one route after the other in
     * every round, and prints each route's figures over all its rounds: a machine whose load drifts during the run
     * then weighs on every route alike, so the ratios between them hold.
     */
    private List<Figures> inRounds(List<Route> routes) throws Exception {
        int rounds = Math.max(1, Math.min(ROUNDS, seconds));
        long sliceMillis = seconds * 1000L / rounds;
        System.out.printf("(%d rounds of %d ms per path, the paths in turn in each round, %d ms after each opens)%n",
                rounds, sliceMillis, SLICE_SETTLE_MS);
        List<Histogram> merged = new ArrayList<>();
        long[] lost = new long[routes.size()];
        for (int i = 0; i < routes.size(); i++) {
            merged.add(new Histogram(60_000_000L, 3));
        }
        for (int r = 0; r < rounds; r++) {
            for (int i = 0; i < routes.size(); i++) {
                Route route = routes.get(i);
                try (BenchRobot robot = new BenchRobot(1_000_000_000L / rateHz, route.channels())) {
                    Path path = route.factory().open(robot);
                    try (SampleClient client = path.connector().connect(path.port())) {
                        await(() -> client.total() > 0, 20_000, route.name() + ": no sample reached the client");
                        Thread.sleep(SLICE_SETTLE_MS);
                        client.startRecording();
                        Thread.sleep(sliceMillis);
                        client.stopRecording();
                        merged.get(i).add(client.latencyMicros());
                        lost[i] += client.missing();
                    } finally {
                        path.closer().close();
                    }
                }
            }
        }
        List<Figures> figures = new ArrayList<>();
        for (int i = 0; i < routes.size(); i++) {
            Histogram h = merged.get(i);
            System.out.printf("%-44s %8d %8d %8d %8d %8d %8d%n", routes.get(i).name(), h.getTotalCount(), lost[i],
                    h.getValueAtPercentile(50), h.getValueAtPercentile(99), h.getValueAtPercentile(99.9),
                    h.getMaxValue());
            figures.add(new Figures(h.getTotalCount(), h.getValueAtPercentile(50), h.getValueAtPercentile(99),
                    h.getValueAtPercentile(99.9), h.getMaxValue()));
        }
        return figures;
    }

    private static void ratios(String name, Figures f, Figures relay1, Figures relay4) {
        System.out.printf("  %-44s %5.2f / %5.2f   %5.2f / %5.2f%n", name, f.p50() / (double) Math.max(1, relay1.p50()),
                f.p99() / (double) Math.max(1, relay1.p99()), f.p50() / (double) Math.max(1, relay4.p50()),
                f.p99() / (double) Math.max(1, relay4.p99()));
    }

    /** What the client connects to, how to take it down, and how the client connects (plain by default). */
    record Path(int port, AutoCloseable closer, Daemon daemon, Connector connector) {
        Path(int port, AutoCloseable closer) {
            this(port, closer, null);
        }

        Path(int port, AutoCloseable closer, Daemon daemon) {
            this(port, closer, daemon, SampleClient::new);
        }
    }

    /** Makes the client of a path's port. */
    interface Connector {
        SampleClient connect(int port) throws IOException;
    }

    /** One path's figures: the latency percentiles [µs] and the samples measured. */
    record Figures(long samples, long p50, long p99, long p999, long max) {
    }

    interface PathFactory {
        Path open(BenchRobot robot) throws Exception;
    }

    /** Runs a path for the warm-up time without measuring or printing anything. */
    void quietly(PathFactory factory, BenchRobot.Channels channels) throws Exception {
        try (BenchRobot robot = new BenchRobot(1_000_000_000L / rateHz, channels)) {
            Path path = factory.open(robot);
            try (SampleClient client = path.connector().connect(path.port())) {
                await(() -> client.total() > 0, 20_000, "warm-up: no sample reached the client");
                Thread.sleep(warmupS * 1000L);
            } finally {
                path.closer().close();
            }
        }
    }

    /** One measurement of a path; {@code during} runs once the client has had its first sample (may be null). */
    Figures measure(String name, PathFactory factory) throws Exception {
        return measure(name, factory, null);
    }

    interface During {
        AutoCloseable start(Path path) throws Exception;
    }

    Figures measure(String name, PathFactory factory, During during) throws Exception {
        return measure(name, BenchRobot.Channels.NUMBER, factory, during);
    }

    Figures measure(String name, BenchRobot.Channels channels, PathFactory factory, During during) throws Exception {
        try (BenchRobot robot = new BenchRobot(1_000_000_000L / rateHz, channels)) {
            Path path = factory.open(robot);
            AutoCloseable extra = null;
            try (SampleClient client = path.connector().connect(path.port())) {
                await(() -> client.total() > 0, 20_000, name + ": no sample reached the client");
                extra = during == null ? null : during.start(path);
                Thread.sleep(warmupS * 1000L);
                long sentBefore = robot.sent();
                client.startRecording();
                Thread.sleep(seconds * 1000L);
                client.stopRecording();
                long sent = robot.sent() - sentBefore;
                Histogram h = client.latencyMicros();
                System.out.printf("%-44s %8d %8d %8d %8d %8d %8d%n", name, client.samples(), client.missing(),
                        h.getValueAtPercentile(50), h.getValueAtPercentile(99), h.getValueAtPercentile(99.9),
                        h.getMaxValue());
                if (client.samples() < sent * 0.9) {
                    System.out.printf("  note: the robot sent %d readings in the window%n", sent);
                }
                return new Figures(client.samples(), h.getValueAtPercentile(50), h.getValueAtPercentile(99),
                        h.getValueAtPercentile(99.9), h.getMaxValue());
            } finally {
                if (extra != null) {
                    extra.close();
                }
                path.closer().close();
            }
        }
    }

    static void await(Callable<Boolean> condition, long millis, String failure) throws Exception {
        long end = System.nanoTime() + millis * 1_000_000;
        while (!condition.call()) {
            if (System.nanoTime() > end) {
                throw new IOException(failure);
            }
            Thread.sleep(10);
        }
    }
}
