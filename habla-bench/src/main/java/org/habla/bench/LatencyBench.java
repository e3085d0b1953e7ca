package org.habla.bench;

import java.io.IOException;
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
 * the methods.
 */
final class LatencyBench {

    /** How long each daemon path runs before any is measured, in a JVM that has not run it yet. */
    static final int JIT_WARMUP_S = 10;

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
        Figures chain = measure("daemon: channel -> pass-through x2", numbers);
        Figures chainOwn = measure("  the same, each method on its own thread", numbersOwn);
        Figures sonarChain = measure("daemon: sonar -> nearest-distance -> relay", BenchRobot.Channels.SONAR, sonar, null);
        Figures sonarChainOwn = measure("  the same, each method on its own thread", BenchRobot.Channels.SONAR,
                sonarOwn, null);
        Figures relay1 = measure("plain relay, 1 thread", robot -> {
            PlainRelay r = new PlainRelay(robot.port(), 0, false);
            return new Path(r.port(), r::close);
        });
        Figures relay4 = measure("plain relay, 4 thread hand-offs", robot -> {
            PlainRelay r = new PlainRelay(robot.port(), 4, false);
            return new Path(r.port(), r::close);
        });
        measure("plain relay, 4 hand-offs, virtual-thread I/O", robot -> {
            PlainRelay r = new PlainRelay(robot.port(), 4, true);
            return new Path(r.port(), r::close);
        });
        System.out.println("  ratios to the plain relay on 1 thread (p50 / p99), and to the one with 4 hand-offs:");
        ratios("daemon: channel -> pass-through x2", chain, relay1, relay4);
        ratios("  the same, own threads", chainOwn, relay1, relay4);
        ratios("daemon: sonar -> nearest-distance -> relay", sonarChain, relay1, relay4);
        ratios("  the same, own threads", sonarChainOwn, relay1, relay4);
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
