package org.habla.bench;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.sim.PortBlock;
import org.habla.sim.scenario.DerivedConfig;

/**
 * Benchmark (l): the daemon's footprint as a user meets it. The simulated robot ({@code habla sim aibo} or
 * {@code habla sim pioneer}) and the daemon ({@code habla run} with a copy of config/aibo.json or
 * config/pioneer.json, its ports moved to a free block) run through the {@code habla} launcher, each in a
 * process of its own with the launcher's JVM options. It measures the time from launching the daemon to every
 * port of its config (control sockets, status, monitor) accepting a connection, and the resident memory
 * (VmRSS of /proc/PID/status) of daemon and simulator at 5, 15, 30 and 60 s after launch (and every minute
 * after, up to {@code seconds}), while a control client reads every exposed socket so samples flow to it.
 * The launcher passes {@code HABLA_JAVA_OPTS} on, so the same run measures other JVM options.
 */
final class FootprintBench {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final long PORT_WAIT_MS = 60_000;
    private static final long BUILD_WAIT_MS = 600_000;

    private final int seconds;
    private final int runs;
    private final List<Integer> marks;
    private final List<String> robots;

    /** Runs {@code runs} times for each of {@code robots} ("aibo", "pioneer"), measuring up to {@code seconds}. */
    FootprintBench(int seconds, int runs, List<String> robots) {
        this.seconds = seconds;
        this.runs = runs;
        this.robots = List.copyOf(robots);
        List<Integer> m = new ArrayList<>();
        for (int s : new int[] {5, 15, 30, 60}) {
            if (s <= seconds) {
                m.add(s);
            }
        }
        for (int s = 120; s <= seconds; s += 60) {
            m.add(s);
        }
        this.marks = List.copyOf(m);
    }

    void run() throws Exception {
        ensureBuilt();
        System.out.printf("%n(l) footprint: launch to every port listening, resident memory at %s s; %d runs per robot;"
                + " daemon JVM options: %s%n", marks, runs, daemonOptions());
        for (String robot : robots) {
            List<Figures> all = new ArrayList<>();
            System.out.printf("%-16s %9s  %-34s  %-34s%n", robot, "ports ms", "daemon RSS MB at " + marks,
                    "simulator RSS MB at " + marks);
            for (int r = 1; r <= runs; r++) {
                Figures f = measure(robot);
                all.add(f);
                System.out.printf("%-16s %9d  %-34s  %-34s%n", "  run " + r, f.portsMs(), Arrays.toString(f.daemonMb()),
                        Arrays.toString(f.simMb()));
            }
            long[] ports = all.stream().mapToLong(Figures::portsMs).toArray();
            long[] daemon = new long[marks.size()];
            long[] sim = new long[marks.size()];
            for (int i = 0; i < marks.size(); i++) {
                int at = i;
                daemon[i] = median(all.stream().mapToLong(f -> f.daemonMb()[at]).toArray());
                sim[i] = median(all.stream().mapToLong(f -> f.simMb()[at]).toArray());
            }
            System.out.printf("%-16s %9d  %-34s  %-34s%n", "  median", median(ports), Arrays.toString(daemon),
                    Arrays.toString(sim));
        }
    }

    /** The daemon's JVM options as the launcher will pass them. */
    private static String daemonOptions() throws IOException {
        String env = System.getenv("HABLA_JAVA_OPTS");
        if (env != null) {
            return "HABLA_JAVA_OPTS=\"" + env + "\"";
        }
        Path file = PioneerRig.home().resolve("config/daemon.jvm-options");
        return Files.isRegularFile(file) ? Files.readString(file).trim() + " (config/daemon.jvm-options)" : "none";
    }

    /** Launch to every port listening [ms], and RSS [MB] of daemon and simulator at each mark (-1: gone). */
    record Figures(long portsMs, long[] daemonMb, long[] simMb) {
    }

    private Figures measure(String robot) throws Exception {
        Path dir = Files.createTempDirectory("habla-footprint");
        int offset = PortBlock.freeOffset();
        Path config = DerivedConfig.write(PioneerRig.home().resolve("config/" + robot + ".json"), 1, offset,
                dir.resolve(robot + ".json"));
        JsonNode root = JSON.readTree(Files.readString(config));
        List<Integer> exposed = new ArrayList<>();
        for (JsonNode m : root.path("methods")) {
            if (m.path("expose").has("port")) {
                exposed.add(m.path("expose").path("port").asInt());
            }
        }
        List<Integer> ports = new ArrayList<>(exposed);
        ports.add(root.path("status").path("port").asInt());
        if (root.path("status").path("monitorPort").asInt() > 0) {
            ports.add(root.path("status").path("monitorPort").asInt());
        }
        Process sim = null;
        Process daemon = null;
        List<Reader> readers = new ArrayList<>();
        try {
            int simPort;
            if (robot.equals("aibo")) {
                sim = launch(dir, "sim.log", "sim", "aibo", "--world", "aibo-arena", "--seed", "7", "--teacher", "on",
                        "--port-base", "" + (10000 + offset), "--truth-port", "" + (10199 + offset));
                simPort = 10020 + offset;   // the controller, which the daemon reaches first
            } else {
                sim = launch(dir, "sim.log", "sim", "pioneer", "--world", "pioneer-hall", "--seed", "7", "--teacher", "on",
                        "--port", "" + (8101 + offset), "--mic-port", "" + (8110 + offset), "--keys-port",
                        "" + (8111 + offset), "--truth-port", "" + (8199 + offset));
                simPort = 8101 + offset;
            }
            if (awaitPorts(List.of(simPort), PORT_WAIT_MS) < 0) {
                throw new IOException("the simulator did not listen on " + simPort + " (alive: " + sim.isAlive()
                        + "); see " + dir.resolve("sim.log"));
            }
            long start = System.nanoTime();
            daemon = launch(dir, "daemon.log", "run", config.toString());
            long portsMs = awaitPorts(ports, PORT_WAIT_MS);
            if (portsMs < 0) {
                throw new IOException("the daemon's ports did not all listen in " + PORT_WAIT_MS / 1000 + " s; see "
                        + dir.resolve("daemon.log"));
            }
            portsMs = TimeUnit.NANOSECONDS.toMillis(portsMs - start);
            for (int port : exposed) {
                readers.add(new Reader(port));
            }
            long[] daemonMb = new long[marks.size()];
            long[] simMb = new long[marks.size()];
            for (int i = 0; i < marks.size(); i++) {
                long due = start + TimeUnit.SECONDS.toNanos(marks.get(i));
                long wait = due - System.nanoTime();
                if (wait > 0) {
                    Thread.sleep(TimeUnit.NANOSECONDS.toMillis(wait));
                }
                daemonMb[i] = rssMb(daemon);
                simMb[i] = rssMb(sim);
            }
            long read = readers.stream().mapToLong(r -> r.bytes.get()).sum();
            if (read == 0) {
                System.out.println("  (the control client read nothing from the exposed sockets; see " + dir + ")");
            }
            return new Figures(portsMs, daemonMb, simMb);
        } finally {
            readers.forEach(Reader::close);
            stop(daemon);
            stop(sim);
        }
    }

    /** Runs the launcher once so that its first-use build is not part of a timed launch. */
    private static void ensureBuilt() throws Exception {
        Process p = new ProcessBuilder(PioneerRig.home().resolve("habla").toString(), "--version")
                .directory(PioneerRig.home().toFile()).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        if (!p.waitFor(BUILD_WAIT_MS, TimeUnit.MILLISECONDS)) {
            p.destroyForcibly();
            throw new IOException("the launcher's build took longer than " + BUILD_WAIT_MS / 1000 + " s");
        }
    }

    /** {@code habla ARGS} through the launcher, output to {@code log} in {@code dir}. */
    private static Process launch(Path dir, String log, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(PioneerRig.home().resolve("habla").toString()));
        cmd.addAll(List.of(args));
        return new ProcessBuilder(cmd).directory(PioneerRig.home().toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve(log).toFile()).start();
    }

    /** The System.nanoTime() at which the last of {@code ports} accepted a connection, or -1 after {@code millis}. */
    private static long awaitPorts(List<Integer> ports, long millis) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        List<Integer> left = new ArrayList<>(ports);
        while (System.nanoTime() < end) {
            left.removeIf(FootprintBench::accepts);
            if (left.isEmpty()) {
                return System.nanoTime();
            }
            Thread.sleep(5);
        }
        return -1;
    }

    private static boolean accepts(int port) {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress("127.0.0.1", port), 100);
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    /** The process's VmRSS in MB, or -1 when it has gone. */
    private static long rssMb(Process p) {
        try {
            for (String line : Files.readAllLines(Path.of("/proc", "" + p.pid(), "status"))) {
                if (line.startsWith("VmRSS:")) {
                    return Long.parseLong(line.replaceAll("[^0-9]", "")) / 1024;
                }
            }
        } catch (IOException | RuntimeException e) {
            return -1;
        }
        return -1;
    }

    private static void stop(Process p) throws InterruptedException {
        if (p != null) {
            p.destroy();
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
        }
    }

    private static long median(long[] v) {
        long[] s = v.clone();
        Arrays.sort(s);
        return s[s.length / 2];
    }

    /** A control client on one exposed socket: reads and counts whatever the daemon sends, until closed. */
    private static final class Reader implements AutoCloseable {

        final AtomicLong bytes = new AtomicLong();
        private final Socket socket = new Socket();
        private final Thread thread;

        Reader(int port) throws IOException {
            socket.connect(new InetSocketAddress("127.0.0.1", port), 5_000);
            thread = Thread.ofPlatform().daemon().name("footprint-reader-" + port).start(this::read);
        }

        private void read() {
            byte[] buf = new byte[8192];
            try (InputStream in = socket.getInputStream()) {
                for (int n; (n = in.read(buf)) >= 0; ) {
                    bytes.addAndGet(n);
                }
            } catch (IOException e) {
                // closed at the end of the run
            }
        }

        @Override
        public void close() {
            try {
                socket.close();
                thread.join(5_000);
            } catch (IOException | InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
