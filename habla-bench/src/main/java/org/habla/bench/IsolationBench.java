// Over 300 lines, on purpose: benchmark (k)'s rounds, its two rigs and the accounting printed under each round
// (CPU time, collector pauses, per-method latency) read the same processes of the rig being measured.
package org.habla.bench;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.habla.cli.DaemonJvm;
import org.habla.graph.RealtimeThreads;
import org.habla.sim.PortBlock;
import org.habla.sim.scenario.DerivedConfig;
import org.habla.testing.DaemonProcess;

/**
 * Benchmark (k): whether heavy methods disturb light ones. The light chain of (a) — a 1 kHz number channel through
 * {@code channel} → {@code pass-through} ×2 to a socket — runs in a daemon process of its own, then in the daemon of
 * config/aibo.json beside the simulated Aibo with its teacher talking and its camera streaming (speech recognition
 * and image segmentation at work), in interleaved rounds; the light chain's percentiles and their ratios are
 * printed. Both daemons run with config/daemon.jvm-options, as {@code habla run} does. Under each round it prints
 * what else held the cores while it was measured: the CPU time of the daemon and of the simulated Aibo (which shares
 * the two cores here, where a real Aibo would not), the daemon's collector pauses, read from its GC log, and each
 * light method's latency from the reading's time to its handling, as the daemon's status reports it. With
 * {@code --realtime N} the daemons run with {@code -Dhabla.realtimePriority=N} ({@link RealtimeThreads}; 0: normal
 * scheduling) whatever the options file says, and the benchmark's robot and client threads take the same class, as
 * a control program run beside such a daemon would.
 */
final class IsolationBench {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final int seconds;
    private final int rounds;
    private final boolean withoutHeavy;
    private final int realtime;
    /** Whether the light chain's methods each get a thread of their own ({@code "thread": "own"}). */
    private final boolean ownThreads;
    /** Method types config/aibo.json runs that count as heavy: their work runs on the background threads. */
    private static final Set<String> HEAVY = Set.of("speech-recognition", "image-segmentation");

    /** Where the light chain runs. */
    private enum Setup {
        ALONE("light chain alone"),
        AIBO("beside speech and vision"),
        /** The Aibo's daemon without its heavy methods and whatever reads from them: the robot's I/O stays. */
        AIBO_WITHOUT_HEAVY("beside the Aibo, no speech/vision");

        final String label;

        Setup(String label) {
            this.label = label;
        }
    }
    /** The processes of the rig being measured and its daemon's GC log (set by {@link #rig}). */
    private static volatile Rig current;

    private record Rig(Process daemon, Process sim, Path gcLog, int statusPort) {
    }

    /**
     * @param withoutHeavy also measure each round in the Aibo's daemon with its heavy methods left out
     * @param realtime     the real-time priority of the sample path's threads, 0 for normal scheduling, -1 for the
     *                     daemon's options file's and normal scheduling for the benchmark's own threads
     */
    IsolationBench(int seconds, int rounds, boolean withoutHeavy, int realtime) {
        this(seconds, rounds, withoutHeavy, realtime, false);
    }

    /** @param ownThreads give each method of the light chain a thread of its own, instead of its link's reader */
    IsolationBench(int seconds, int rounds, boolean withoutHeavy, int realtime, boolean ownThreads) {
        this.ownThreads = ownThreads;
        this.seconds = seconds;
        this.rounds = rounds;
        this.withoutHeavy = withoutHeavy;
        this.realtime = realtime;
    }

    void run() throws Exception {
        System.out.printf("%n(k) a light 1 kHz chain alone and beside the Aibo's speech and vision, %d rounds of %d s%s%s%n",
                rounds, seconds, realtime < 0 ? "" : realtime == 0 ? ", normal scheduling everywhere"
                        : ", robot, daemon and client real-time at priority " + realtime,
                ownThreads ? ", each light method on its own thread" : ", the light chain on its link's reader");
        if (realtime >= 0) {
            System.setProperty(RealtimeThreads.PROPERTY, Integer.toString(realtime)); // the robot's and client's threads
        }
        System.out.printf("%-44s %8s %8s %8s %8s %8s %8s%n", "path", "samples", "lost", "p50 µs", "p99 µs",
                "p99.9 µs", "max µs");
        // Each round is a new daemon process: its warm-up is the latency bench's JIT warm-up, so that neither
        // set-up is measured while the compiler still works on the engine's code.
        LatencyBench latency = new LatencyBench(1_000, LatencyBench.JIT_WARMUP_S, seconds);
        List<LatencyBench.Figures> alone = new ArrayList<>();
        List<LatencyBench.Figures> beside = new ArrayList<>();
        List<LatencyBench.Figures> besideLight = new ArrayList<>();
        for (int r = 1; r <= rounds; r++) {
            alone.add(round(latency, r, Setup.ALONE));
            beside.add(round(latency, r, Setup.AIBO));
            if (withoutHeavy) {
                besideLight.add(round(latency, r, Setup.AIBO_WITHOUT_HEAVY));
            }
        }
        long p50Alone = median(alone.stream().mapToLong(LatencyBench.Figures::p50).toArray());
        long p99Alone = median(alone.stream().mapToLong(LatencyBench.Figures::p99).toArray());
        long p50Beside = median(beside.stream().mapToLong(LatencyBench.Figures::p50).toArray());
        long p99Beside = median(beside.stream().mapToLong(LatencyBench.Figures::p99).toArray());
        System.out.printf("  medians: alone p50 %d µs, p99 %d µs; beside p50 %d µs, p99 %d µs; p99 ratio %.2f (goal <= 1.5)%n",
                p50Alone, p99Alone, p50Beside, p99Beside, p99Beside / (double) Math.max(1, p99Alone));
        if (withoutHeavy) {
            long p99Light = median(besideLight.stream().mapToLong(LatencyBench.Figures::p99).toArray());
            System.out.printf("  beside the Aibo without speech and vision: p50 %d µs, p99 %d µs; p99 ratio %.2f%n",
                    median(besideLight.stream().mapToLong(LatencyBench.Figures::p50).toArray()), p99Light,
                    p99Light / (double) Math.max(1, p99Alone));
        }
    }

    private LatencyBench.Figures round(LatencyBench latency, int r, Setup setup) throws Exception {
        return latency.measure("round " + r + ": " + setup.label, robot -> rig(robot.port(), setup),
                IsolationBench::accounting);
    }

    /**
     * From the client's first sample to the end of the round (the warm-up and the measured window): the CPU the
     * daemon and the simulator used, in cores, and the daemon's collector pauses.
     */
    private static AutoCloseable accounting(LatencyBench.Path path) throws IOException {
        Rig rig = current;
        long start = System.nanoTime();
        long daemonTicks = cpuTicks(rig.daemon());
        long simTicks = rig.sim() == null ? 0 : cpuTicks(rig.sim());
        int gcLines = Files.readAllLines(rig.gcLog()).size();
        status(rig.statusPort()); // starts the methods' latency intervals here
        return () -> {
            double s = (System.nanoTime() - start) / 1e9;
            double daemon = (cpuTicks(rig.daemon()) - daemonTicks) / TICKS_PER_S / s;
            double sim = rig.sim() == null ? 0 : (cpuTicks(rig.sim()) - simTicks) / TICKS_PER_S / s;
            List<String> lines = Files.readAllLines(rig.gcLog());
            List<String> pauses = lines.subList(Math.min(gcLines, lines.size()), lines.size()).stream()
                    .filter(l -> l.contains(" Pause ") && l.endsWith("ms")).toList();
            double pausedMs = pauses.stream().mapToDouble(l -> Double.parseDouble(l.substring(l.lastIndexOf(' ') + 1,
                    l.length() - 2))).sum();
            System.out.printf("    over %.0f s: daemon %.2f cores, simulator %.2f cores; daemon's GC: %d pauses, %.0f ms"
                    + " (%.1f ms/s)%n", s, daemon, sim, pauses.size(), pausedMs, pausedMs / s);
            JsonNode st = status(rig.statusPort());
            StringBuilder hops = new StringBuilder();
            for (JsonNode m : st.path("methods")) {
                if (m.path("id").asText().startsWith("bench-")) {
                    JsonNode l = m.path("latency");
                    hops.append(String.format(" %s %d / %d / %d µs;", m.path("id").asText(), l.path("p50Us").asLong(),
                            l.path("p99Us").asLong(), l.path("maxUs").asLong()));
                }
            }
            System.out.printf("    reading to handled, p50 / p99 / max, as the daemon's status reports it:%s%n", hops);
        };
    }

    /** Clock ticks per second of /proc/PID/stat's times (USER_HZ, 100 on Linux). */
    private static final double TICKS_PER_S = 100;

    /** User and system time of a process so far, in clock ticks; 0 where /proc is missing or it has gone. */
    private static long cpuTicks(Process p) {
        try {
            String stat = Files.readString(Path.of("/proc/" + p.pid() + "/stat"));
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return Long.parseLong(f[11]) + Long.parseLong(f[12]); // utime, stime (fields 14 and 15)
        } catch (IOException | RuntimeException e) {
            return 0;
        }
    }

    private static long median(long[] v) {
        java.util.Arrays.sort(v);
        return v[v.length / 2];
    }

    /**
     * The methods of {@code root} but the heavy ones and, again and again, those that read from a method left out
     * (their wiring would be broken).
     */
    private static void dropHeavy(ObjectNode root) {
        Set<String> gone = new java.util.HashSet<>();
        ArrayNode methods = (ArrayNode) root.get("methods");
        boolean changed = true;
        while (changed) {
            changed = false;
            for (java.util.Iterator<JsonNode> it = methods.iterator(); it.hasNext(); ) {
                JsonNode m = it.next();
                boolean reads = false;
                for (JsonNode source : m.path("inputs")) {
                    String from = source.asText();
                    reads |= gone.contains(from.contains(".") ? from.substring(0, from.indexOf('.')) : from);
                }
                if (HEAVY.contains(m.path("type").asText()) || reads) {
                    gone.add(m.path("id").asText());
                    it.remove();
                    changed = true;
                }
            }
        }
    }

    /** A daemon process with the light chain, alone or in config/aibo.json beside the simulated Aibo. */
    private LatencyBench.Path rig(int robotPort, Setup setup) throws Exception {
        boolean aibo = setup != Setup.ALONE;
        Path dir = Files.createTempDirectory("habla-isolation");
        int offset = PortBlock.freeOffset();
        ObjectNode root;
        if (aibo) {
            Path derived = DerivedConfig.write(PioneerRig.home().resolve("config/aibo.json"), 1, offset,
                    dir.resolve("aibo.json"));
            root = (ObjectNode) JSON.readTree(Files.readString(derived));
            if (setup == Setup.AIBO_WITHOUT_HEAVY) {
                dropHeavy(root);
            }
        } else {
            root = JSON.createObjectNode().put("system", "bench-light");
            root.putArray("interfaces");
            root.putArray("methods");
        }
        int port = DaemonProcess.freePorts(1)[0];
        int statusPort = DaemonProcess.freePorts(1)[0];
        root.putObject("status").put("port", statusPort).put("monitorPort", 0);
        ((ArrayNode) root.get("interfaces")).add(JSON.readTree("""
                {"id": "bench", "driver": "habla", "address": "127.0.0.1:%d", "params": {"channels": %s}}
                """.formatted(robotPort, BenchRobot.CHANNELS_JSON)));
        String relay = "\"params\": {\"kind\": \"number\", \"delivery\": \"queue\", \"capacity\": 4096}"
                + (ownThreads ? ", \"thread\": \"own\"" : "");
        ArrayNode methods = (ArrayNode) root.get("methods");
        methods.add(JSON.readTree("{\"id\": \"bench-s\", \"type\": \"channel\", \"layer\": \"sensors_actuators\","
                + " \"inputs\": {\"in\": \"@bench.value\"}, " + relay + "}"));
        methods.add(JSON.readTree("{\"id\": \"bench-p\", \"type\": \"pass-through\", \"layer\": \"processing\","
                + " \"inputs\": {\"in\": \"bench-s.out\"}, " + relay + "}"));
        methods.add(JSON.readTree("{\"id\": \"bench-v\", \"type\": \"pass-through\", \"layer\": \"virtual\","
                + " \"inputs\": {\"in\": \"bench-p.out\"}, " + relay + ", \"expose\": {\"port\": " + port
                + ", \"name\": \"value\"}}"));
        Path config = dir.resolve("daemon.json");
        Files.writeString(config, JSON.writerWithDefaultPrettyPrinter().writeValueAsString(root));
        List<Process> processes = new ArrayList<>();
        AutoCloseable closer = () -> {
            for (Process p : processes) {
                p.destroy();
                p.waitFor(10, java.util.concurrent.TimeUnit.SECONDS);
            }
        };
        try {
            Process sim = null;
            if (aibo) {
                sim = launch(dir, "sim.log", List.of(), "sim", "aibo", "--world", "aibo-arena", "--seed", "7",
                        "--teacher", "on", "--port-base", "" + (10000 + offset), "--truth-port", "" + (10199 + offset));
                processes.add(sim);
            }
            Path gcLog = dir.resolve("gc.log");
            List<String> options = new ArrayList<>(List.of("-Xlog:gc:file=" + gcLog));
            if (System.getProperty(RealtimeThreads.PROPERTY) != null) {
                options.add("-D" + RealtimeThreads.PROPERTY + "=" + RealtimeThreads.configured());
            }
            Process daemon = launch(dir, "daemon.log", options, "run", config.toString());
            processes.add(daemon);
            current = new Rig(daemon, sim, gcLog, statusPort);
            awaitReady(statusPort, 180_000, dir);
            return new LatencyBench.Path(port, closer);
        } catch (Exception e) {
            closer.close();
            throw e;
        }
    }

    /** {@code habla ARGS} in a JVM of its own, with the daemon's options and {@code jvmOptions}. */
    private static Process launch(Path dir, String log, List<String> jvmOptions, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "--enable-native-access=ALL-UNNAMED"));
        cmd.addAll(DaemonJvm.options(PioneerRig.home(), args[0]));
        cmd.addAll(jvmOptions);
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "-Dhabla.home=" + PioneerRig.home(),
                "org.habla.cli.Habla"));
        cmd.addAll(List.of(args));
        return new ProcessBuilder(cmd).directory(PioneerRig.home().toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve(log).toFile()).start();
    }

    /** The daemon's status, read once. */
    private static JsonNode status(int statusPort) throws IOException {
        try (Socket s = new Socket("127.0.0.1", statusPort)) {
            s.setSoTimeout(5_000);
            return JSON.readTree(new BufferedReader(new InputStreamReader(s.getInputStream(),
                    StandardCharsets.UTF_8)).readLine());
        }
    }

    /** Waits (bounded) until every link is up and every method ready, as the status endpoint says. */
    private static void awaitReady(int statusPort, long millis, Path dir) throws Exception {
        try {
            org.habla.sim.scenario.DaemonReadiness.await(statusPort, millis, () -> true);
        } catch (IOException e) {
            throw new IOException(e.getMessage() + "; see " + dir, e);
        }
    }
}
