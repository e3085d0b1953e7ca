package org.habla.bench;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.habla.cli.DaemonJvm;
import org.habla.sim.PortBlock;
import org.habla.sim.scenario.DerivedConfig;

/**
 * The simulated Pioneer and the daemon, each in a process of its own as a user runs them ({@code habla sim
 * pioneer}, {@code habla run config/pioneer.json} with its ports moved to a free block, no heap limit of ours),
 * for the chaos benchmarks: it tells the daemon's resident memory and thread count from {@code /proc}, and
 * reads its status endpoint.
 */
final class PioneerRig implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();

    final Path dir;
    final Path config;
    private final int offset;
    private Process sim;
    private Process daemon;

    /** Writes the derived config, changed by {@code tweak}, into a fresh folder. */
    PioneerRig(Consumer<ObjectNode> tweak) throws IOException {
        dir = Files.createTempDirectory("habla-chaos");
        offset = PortBlock.freeOffset();
        config = DerivedConfig.write(home().resolve("config/pioneer.json"), 1, offset, dir.resolve("daemon.json"));
        ObjectNode root = (ObjectNode) JSON.readTree(Files.readString(config));
        tweak.accept(root);
        Files.writeString(config, JSON.writerWithDefaultPrettyPrinter().writeValueAsString(root));
    }

    /** The project folder (bench/run runs from it). */
    static Path home() {
        Path dir = Path.of("").toAbsolutePath();
        while (dir != null && !Files.isDirectory(dir.resolve("habla-core"))) {
            dir = dir.getParent();
        }
        if (dir == null) {
            throw new IllegalStateException("run from the HABLA folder");
        }
        return dir;
    }

    /** Starts the simulator, then the daemon, and waits (bounded) until every link is up. */
    void start() throws Exception {
        sim = launch("sim.log", "sim", "pioneer", "--world", "pioneer-hall", "--seed", "7", "--teacher", "off",
                "--port", "" + (8101 + offset), "--mic-port", "" + (8110 + offset), "--keys-port", "" + (8111 + offset),
                "--truth-port", "" + (8199 + offset));
        if (!awaitPort(8101 + offset, 60_000)) {
            throw new IOException("the simulator did not listen; see " + dir.resolve("sim.log"));
        }
        daemon = launch("daemon.log", "run", config.toString());
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        String missing = "?";
        while (System.nanoTime() < end) {
            try {
                JsonNode st = status();
                missing = "";
                for (JsonNode i : st.path("interfaces")) {
                    if (!i.path("up").asBoolean()) {
                        missing += i.path("id").asText() + " ";
                    }
                }
                if (missing.isEmpty()) {
                    return;
                }
            } catch (IOException e) {
                missing = e.toString();
            }
            if (!daemon.isAlive()) {
                throw new IOException("the daemon exited; see " + dir.resolve("daemon.log"));
            }
            Thread.sleep(200);
        }
        throw new IOException("links not up after 120 s: " + missing + "; see " + dir.resolve("daemon.log"));
    }

    private Process launch(String log, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "--enable-native-access=ALL-UNNAMED"));
        cmd.addAll(DaemonJvm.options(home(), args[0])); // the daemon's, as ./habla passes them
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "-Dhabla.home=" + home(), "org.habla.cli.Habla"));
        cmd.addAll(List.of(args));
        return new ProcessBuilder(cmd).directory(home().toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve(log).toFile()).start();
    }

    private static boolean awaitPort(int port, long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000;
        while (System.nanoTime() < end) {
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress("127.0.0.1", port), 200);
                return true;
            } catch (IOException e) {
                Thread.sleep(100);
            }
        }
        return false;
    }

    int port(String socket) throws IOException {
        return DerivedConfig.exposedPort(config, socket);
    }

    int statusPort() {
        return 7099 + offset;
    }

    /** Every control socket's port. */
    List<Integer> controlPorts() throws IOException {
        List<Integer> ports = new ArrayList<>();
        for (JsonNode m : JSON.readTree(Files.readString(config)).path("methods")) {
            if (m.path("expose").has("port")) {
                ports.add(m.path("expose").path("port").asInt());
            }
        }
        return ports;
    }

    /** The daemon's status snapshot. */
    JsonNode status() throws IOException {
        try (Socket s = new Socket("127.0.0.1", statusPort())) {
            s.setSoTimeout(10_000);
            String line = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8)).readLine();
            if (line == null) {
                throw new IOException("the status endpoint closed without an answer");
            }
            return JSON.readTree(line);
        }
    }

    /** The daemon's resident memory in MB and its thread count, from /proc. */
    ProcessFigures figures() throws IOException {
        long rssKb = -1;
        int threads = -1;
        for (String line : Files.readAllLines(Path.of("/proc", "" + daemon.pid(), "status"))) {
            if (line.startsWith("VmRSS:")) {
                rssKb = Long.parseLong(line.replaceAll("[^0-9]", ""));
            } else if (line.startsWith("Threads:")) {
                threads = Integer.parseInt(line.replaceAll("[^0-9]", ""));
            }
        }
        return new ProcessFigures(rssKb / 1024.0, threads);
    }

    /** Asks the daemon's JVM for a full collection (jcmd GC.run), to tell memory it holds from memory it could give back. */
    void fullGc() throws IOException, InterruptedException {
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "jcmd").toString(),
                "" + daemon.pid(), "GC.run").redirectErrorStream(true).redirectOutput(dir.resolve("jcmd.log").toFile())
                .start();
        if (!p.waitFor(60, TimeUnit.SECONDS)) {
            p.destroyForcibly();
        }
    }

    /** Resident memory [MB] and threads of a process. */
    record ProcessFigures(double rssMb, int threads) {
    }

    boolean daemonAlive() {
        return daemon != null && daemon.isAlive();
    }

    @Override
    public void close() throws InterruptedException {
        for (Process p : new Process[] {daemon, sim}) {
            if (p != null) {
                p.destroy();
                if (!p.waitFor(10, TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            }
        }
    }
}
