package org.habla.sim.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.habla.sim.scenario.DerivedConfig;
import org.habla.sim.scenario.DaemonReadiness;
import org.habla.sim.scenario.TruthLink;
import org.habla.testing.DaemonProcess;

/**
 * A robot set-up as a user deploys it, for end-to-end tests: the simulated robot in its own JVM, the
 * daemon with the robot's committed config (ports moved to a free block) in another, and control
 * programs in Python talking to the contract's sockets. The ground truth comes from the simulator.
 */
final class SimulatedDeployment implements AutoCloseable {

    static final Path HOME = Path.of("").toAbsolutePath().getParent();
    private static final ObjectMapper JSON = new ObjectMapper();

    final String robot;
    final double speed;
    final int offset;
    final Path dir;
    final Path config;
    private final List<String> simArgs;
    DaemonProcess sim;
    DaemonProcess daemon;
    TruthLink truth;

    /**
     * @param tweak changes to the daemon's config (e.g. a longer action) before it starts
     */
    SimulatedDeployment(String robot, String world, double speed, Path dir, Consumer<ObjectNode> tweak)
            throws IOException {
        this.robot = robot;
        this.speed = speed;
        this.dir = dir;
        this.offset = freeOffset();
        this.config = DerivedConfig.write(HOME.resolve("config/" + robot + ".json"), speed, offset, dir.resolve("daemon.json"));
        ObjectNode root = (ObjectNode) JSON.readTree(Files.readString(config));
        tweak.accept(root);
        Files.writeString(config, JSON.writerWithDefaultPrettyPrinter().writeValueAsString(root));
        simArgs = new ArrayList<>(List.of("sim", robot, "--world", world, "--speed", fmt(speed), "--seed", "7",
                "--truth-port", "" + truthPort(), "--teacher", "off"));
        if (robot.equals("pioneer")) {
            simArgs.addAll(List.of("--port", "" + (8101 + offset), "--mic-port", "" + (8110 + offset),
                    "--keys-port", "" + (8111 + offset)));
        } else {
            simArgs.addAll(List.of("--port-base", "" + (10000 + offset)));
        }
    }

    int truthPort() {
        return (robot.equals("pioneer") ? 8199 : 10199) + offset;
    }

    int port(String socketName) throws IOException {
        return DerivedConfig.exposedPort(config, socketName);
    }

    /** Starts (or restarts) the simulator and connects to its ground truth. */
    void startSimulator() throws Exception {
        sim = DaemonProcess.start(dir.resolve("sim-" + System.nanoTime() + ".log"), simArgs.toArray(String[]::new));
        truth = TruthLink.connect(truthPort(), 60_000);
        assertThat(truth.awaitTime(0, 10_000)).as("ground truth streams").isNotNull();
    }

    void killSimulator() throws Exception {
        truth.close();
        sim.terminate(5_000);
    }

    void startDaemon() throws Exception {
        startDaemon(new String[0]);
    }

    /** Starts the daemon with extra arguments to {@code habla run} (e.g. {@code --record FILE}). */
    void startDaemon(String... extra) throws Exception {
        List<String> args = new ArrayList<>(List.of("run", config.toString(), "--time-scale", fmt(speed)));
        args.addAll(List.of(extra));
        Path log = dir.resolve(extra.length == 0 ? "daemon.log" : "daemon-" + System.nanoTime() + ".log");
        daemon = DaemonProcess.start(log, args.toArray(String[]::new));
        assertThat(DaemonProcess.awaitPort(port("distance_angle"), 60_000)).as("daemon sockets up; log: %s", log)
                .isTrue();
    }

    /** Waits until every method of the daemon is ready (models loaded) and every link to the robot is up, as its status endpoint tells. */
    void awaitReady(long timeoutMs) throws Exception {
        int port = JSON.readTree(Files.readString(config)).path("status").path("port").asInt();
        DaemonReadiness.await(port, timeoutMs, () -> daemon.alive());
    }

    /**
     * What the daemon's status endpoint says of these methods (readiness, inputs with their dropped and conflated
     * counts): the account of where a sample went when an end-to-end check misses it.
     */
    String methodStatus(String... ids) {
        try {
            int port = JSON.readTree(Files.readString(config)).path("status").path("port").asInt();
            List<String> out = new ArrayList<>();
            for (JsonNode m : DaemonReadiness.snapshot(port).path("methods")) {
                if (List.of(ids).contains(m.path("id").asText())) {
                    out.add(m.toString());
                }
            }
            return String.join("\n", out);
        } catch (IOException e) {
            return "(no status: " + e.getMessage() + ")";
        }
    }

    /** Puts the robot at a pose (world frame) and returns the first ground truth after it. */
    JsonNode place(double x, double y, double theta) throws Exception {
        ObjectNode reset = TruthLink.op("reset");
        reset.putObject("robot").put("xM", x).put("yM", y).put("thetaRad", theta);
        double t = truth.latest().path("t").asDouble();
        truth.send(reset);
        return truth.awaitTime(t + 0.2, 30_000);
    }

    /** The ground truth at least {@code seconds} of simulated time after now. */
    JsonNode after(double seconds) throws InterruptedException {
        double t = truth.latest().path("t").asDouble();
        return truth.awaitTime(t + seconds, (long) (seconds / speed * 1000) + 10_000);
    }

    /** Runs contract_probe.py with these arguments and returns its JSON lines. */
    List<JsonNode> probe(long timeoutMs, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of("python3", "-u",
                Path.of("src/test/resources/e2e/contract_probe.py").toAbsolutePath().toString()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectError(dir.resolve("probe-err.log").toFile());
        pb.environment().put("PYTHONPATH", HOME.resolve("clients/python/src").toString());
        Process p = pb.start();
        List<JsonNode> lines = new ArrayList<>();
        try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = r.readLine()) != null) {
                lines.add(JSON.readTree(line));
            }
        }
        if (!p.waitFor(timeoutMs, TimeUnit.MILLISECONDS)) {
            p.destroyForcibly();
            throw new AssertionError("the Python client did not finish within " + timeoutMs + " ms");
        }
        assertThat(p.exitValue()).as("python client exit; stderr in %s: %s", dir.resolve("probe-err.log"),
                Files.readString(dir.resolve("probe-err.log"))).isZero();
        return lines;
    }

    /** Starts contract_probe.py in the background; its stdout lines come through the returned process. */
    Process probeAsync(String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of("python3", "-u",
                Path.of("src/test/resources/e2e/contract_probe.py").toAbsolutePath().toString()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectError(dir.resolve("probe-async-err.log").toFile());
        pb.environment().put("PYTHONPATH", HOME.resolve("clients/python/src").toString());
        return pb.start();
    }

    @Override
    public void close() throws Exception {
        if (daemon != null) {
            daemon.close();
        }
        if (truth != null) {
            truth.close();
        }
        if (sim != null) {
            sim.close();
        }
    }

    static String fmt(double x) {
        return x == Math.rint(x) ? String.valueOf((long) x) : String.valueOf(x);
    }

    static double angleDiff(double a, double b) {
        double d = a - b;
        while (d > Math.PI) {
            d -= 2 * Math.PI;
        }
        while (d < -Math.PI) {
            d += 2 * Math.PI;
        }
        return d;
    }

    private static int freeOffset() throws IOException {
        return org.habla.sim.PortBlock.freeOffset();
    }
}
