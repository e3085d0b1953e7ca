package org.habla.bench;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import org.HdrHistogram.Histogram;
import org.habla.cli.DaemonJvm;
import org.habla.net.Frame;
import org.habla.net.FrameReader;
import org.habla.methods.speech.EvalSet;
import org.habla.methods.speech.Utterances;
import org.habla.net.FrameWriter;
import org.habla.sample.AudioChunk;
import org.habla.sim.scenario.DaemonReadiness;
import org.habla.sim.scenario.DerivedConfig;

/**
 * {@code bench/run aibo-speech}: end of speech → phrase on a socket in the Aibo's own daemon, beside its vision. The
 * simulated Aibo runs ({@code habla sim aibo}, teacher away) and the daemon runs config/aibo.json (or
 * {@code --config}) in a process of its own with the daemon's JVM options and the launcher's allocator settings,
 * every method of the config at work: the camera streams and image segmentation runs on every frame. Only the
 * input of {@code audio} changes: instead of the robot's microphone it takes a stream written to a socket, into
 * which held-out voices of the speech evaluation set ({@code bench/speech/make-eval-set.sh}) are played in real
 * time, clean and with white noise; {@code speech.words} is exposed on another socket. For each phrase heard right,
 * the time from the end of its speech to its line on the socket; the daemon's CPU time and the machine's load
 * average over the playing; the speech method's status line at the end.
 */
final class AiboSpeechBench {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final int CHUNK_MS = 32;
    private static final int RATE_HZ = 16_000;
    private static final long READY_WAIT_MS = 180_000;
    /** After the last chunk of a stream: time for its last phrase to come out. */
    private static final long TAIL_MS = 2_000;
    /** A phrase on the socket is matched to an item of its text that ended at most this long before it. */
    private static final double MATCH_WITHIN_S = 6;
    /** Clock ticks per second of /proc/PID/stat's times (USER_HZ). */
    private static final double TICKS_PER_S = 100;

    private final Path config;
    private final int voices;
    private final int portOffset;
    private final int nice;

    /**
     * @param nice the daemon's and simulator's nice value (0: as launched; negative: ahead of the other processes of
     *             a shared machine, as a robot's own computer would run them)
     */
    AiboSpeechBench(Path config, int voices, int portOffset, int nice) {
        this.config = config;
        this.voices = voices;
        this.portOffset = portOffset;
        this.nice = nice;
    }

    void run() throws Exception {
        Path dir = Files.createTempDirectory("habla-aibo-speech");
        Path derived = DerivedConfig.write(PioneerRig.home().resolve(config), 1, portOffset, dir.resolve("aibo.json"));
        ObjectNode root = (ObjectNode) JSON.readTree(Files.readString(derived));
        int micPort = 7021 + portOffset;
        int wordsPort = 7022 + portOffset;
        int statusPort = root.path("status").path("port").asInt();
        rewire(root, micPort, wordsPort);
        Path daemonConfig = dir.resolve("daemon.json");
        Files.writeString(daemonConfig, JSON.writerWithDefaultPrettyPrinter().writeValueAsString(root));
        List<Process> processes = new ArrayList<>();
        try {
            processes.add(launch(dir, nice, "sim.log", "sim", "aibo", "--world", "aibo-arena", "--seed", "7", "--teacher",
                    "off", "--port-base", "" + (10000 + portOffset), "--truth-port", "" + (10199 + portOffset)));
            Process daemon = launch(dir, nice, "daemon.log", "run", daemonConfig.toString());
            processes.add(daemon);
            DaemonReadiness.await(statusPort, READY_WAIT_MS, daemon::isAlive);
            System.out.printf("%n(i) speech in the Aibo's daemon beside vision (%s, port offset %d, nice %d; logs in %s)%n",
                    config, portOffset, nice, dir);
            play(daemon, micPort, wordsPort, statusPort);
        } finally {
            for (Process p : processes) {
                p.destroy();
                if (!p.waitFor(10, TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            }
        }
    }

    /**
     * Feeds every method that reads the microphone's audio ({@code audio}, and {@code speech} when it cuts the stream
     * itself) from a socket of its own and exposes {@code speech.words}; everything else stays.
     */
    private static void rewire(ObjectNode root, int micPort, int wordsPort) throws IOException {
        ArrayNode methods = (ArrayNode) root.get("methods");
        for (JsonNode m : methods) {
            ObjectNode inputs = (ObjectNode) m.get("inputs");
            if (inputs == null) {
                continue;
            }
            List<String> ports = new ArrayList<>();
            inputs.fieldNames().forEachRemaining(ports::add);
            for (String port : ports) {
                if (inputs.path(port).asText().equals("microphone.audio")) {
                    inputs.put(port, "bench-mic.out");
                }
            }
        }
        methods.add(JSON.readTree("""
                {"id": "bench-mic", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
                 "params": {"kind": "audio", "delivery": "queue", "capacity": 256}, "expose": {"port": %d, "name": "mic"}}
                """.formatted(micPort)));
        methods.add(JSON.readTree("""
                {"id": "bench-words", "type": "pass-through", "layer": "virtual", "inputs": {"in": "speech.words"},
                 "params": {"kind": "text", "delivery": "queue"}, "expose": {"port": %d, "name": "words"}}
                """.formatted(wordsPort)));
    }

    private void play(Process daemon, int micPort, int wordsPort, int statusPort) throws Exception {
        List<EvalSet.Voice> heldOut = EvalSet.read(PioneerRig.home().resolve("target/speech-eval")).stream()
                .filter(EvalSet.Voice::heldOut).toList();
        Histogram all = new Histogram(60_000_000L, 3);
        int right = 0;
        int items = 0;
        double audioS = 0;
        try (Socket in = connect(micPort); Socket out = connect(wordsPort)) {
            ConcurrentLinkedQueue<Object[]> arrivals = new ConcurrentLinkedQueue<>();
            read(out, arrivals);
            read(in, new ConcurrentLinkedQueue<>()); // replies to writes
            FrameWriter w = new FrameWriter(in.getOutputStream());
            long ticks0 = cpuTicks(daemon);
            long wall0 = System.nanoTime();
            for (EvalSet.Voice v : heldOut.subList(0, Math.min(voices, heldOut.size()))) {
                for (String condition : List.of("clean", "noise20")) {
                    byte[] pcm = pcm(v, condition);
                    arrivals.clear();
                    int chunk = RATE_HZ * CHUNK_MS / 1000 * 2;
                    long t0 = System.nanoTime();
                    for (int at = 0, k = 0; at < pcm.length; at += chunk, k++) {
                        long wait = t0 + (long) ((k + 1) * CHUNK_MS * 1e6) - System.nanoTime();
                        if (wait > 0) {
                            Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
                        }
                        ObjectNode header = JSON.createObjectNode().put("op", "write").put("input", "in")
                                .put("kind", "audio").put("rateHz", RATE_HZ).put("channels", 1).put("bits", 16);
                        w.send(new Frame(header, Arrays.copyOfRange(pcm, at, Math.min(pcm.length, at + chunk))));
                    }
                    Thread.sleep(TAIL_MS);
                    audioS += pcm.length / (RATE_HZ * 2.0);
                    Histogram h = new Histogram(60_000_000L, 3);
                    java.util.Set<EvalSet.Item> matched = new java.util.HashSet<>();
                    for (Object[] arrival : arrivals) {
                        double atS = ((Long) arrival[0] - t0) / 1e9;
                        // the latest item of this phrase that ended before it, not matched yet, however late it came
                        EvalSet.Item said = null;
                        for (EvalSet.Item it : v.items()) {
                            if (it.endS() <= atS && atS - it.endS() <= MATCH_WITHIN_S && it.inGrammar()
                                    && it.text().equals(arrival[1]) && !matched.contains(it)) {
                                said = it;
                            }
                        }
                        if (said != null) {
                            matched.add(said);
                            h.recordValue(Math.max(0, Math.round((atS - said.endS()) * 1e6)));
                        }
                    }
                    all.add(h);
                    right += (int) h.getTotalCount();
                    int in2 = (int) v.items().stream().filter(EvalSet.Item::inGrammar).count();
                    items += in2;
                    System.out.printf("  %-20s %-8s %3d of %d phrases right: p50 %5.0f ms   p90 %5.0f ms   max %5.0f ms"
                            + "   (load %s)%n", v.name(), condition, h.getTotalCount(), in2,
                            h.getValueAtPercentile(50) / 1e3, h.getValueAtPercentile(90) / 1e3, h.getMaxValue() / 1e3,
                            Benchmarks.loadAverage());
                }
            }
            double wallS = (System.nanoTime() - wall0) / 1e9;
            double cores = (cpuTicks(daemon) - ticks0) / TICKS_PER_S / wallS;
            System.out.printf("end of speech -> phrase on the socket, %.0f s of speech played in real time: %d phrases right "
                    + "of %d%np50 %.0f ms   p90 %.0f ms   p99 %.0f ms   max %.0f ms%n", audioS, right, items,
                    all.getValueAtPercentile(50) / 1e3, all.getValueAtPercentile(90) / 1e3,
                    all.getValueAtPercentile(99) / 1e3, all.getMaxValue() / 1e3);
            System.out.printf("the daemon used %.2f cores over the %.0f s (vision, speech and the rest); load average at "
                    + "the end %s; daemon RSS %d MB%n", cores, wallS, Benchmarks.loadAverage(), rssMb(daemon));
            System.out.println("speech status: " + speechStatus(statusPort));
        }
    }

    /** The readiness line of the {@code speech} method, from the daemon's status endpoint. */
    private static String speechStatus(int statusPort) {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), statusPort)) {
            s.setSoTimeout(5_000);
            JsonNode st = JSON.readTree(new BufferedReader(new InputStreamReader(s.getInputStream(),
                    StandardCharsets.UTF_8)).readLine());
            for (JsonNode m : st.path("methods")) {
                if (m.path("id").asText().equals("speech")) {
                    return m.toString();
                }
            }
            return "no speech method in the status";
        } catch (IOException e) {
            return "status unreadable: " + e.getMessage();
        }
    }

    private static void read(Socket s, ConcurrentLinkedQueue<Object[]> into) {
        Thread.ofPlatform().daemon().start(() -> {
            try {
                FrameReader r = new FrameReader(new BufferedInputStream(s.getInputStream()), 1 << 20, 1 << 24);
                for (Frame f = r.read(); f != null; f = r.read()) {
                    if (f.header().path("type").asText().equals("sample")) {
                        into.add(new Object[] {System.nanoTime(), f.header().path("value").asText()});
                    }
                }
            } catch (IOException e) {
                // closed at the end
            }
        });
    }

    private static Socket connect(int port) throws IOException {
        Socket s = new Socket(InetAddress.getLoopbackAddress(), port);
        s.setTcpNoDelay(true);
        return s;
    }

    /** {@code habla ARGS} in a JVM of its own at {@code nice}, with the daemon's options and the launcher's allocator settings. */
    private static Process launch(Path dir, int nice, String log, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(nice == 0 ? List.of() : List.of("nice", "-n", Integer.toString(nice)));
        cmd.addAll(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "--enable-native-access=ALL-UNNAMED"));
        cmd.addAll(DaemonJvm.options(PioneerRig.home(), args[0]));
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "-Dhabla.home=" + PioneerRig.home(),
                "org.habla.cli.Habla"));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(PioneerRig.home().toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve(log).toFile());
        pb.environment().putIfAbsent("MALLOC_ARENA_MAX", "2");
        pb.environment().putIfAbsent("MALLOC_TRIM_THRESHOLD_", "1048576");
        return pb.start();
    }

    /** User and system time of a process so far, in clock ticks; 0 where /proc is missing or it has gone. */
    private static long cpuTicks(Process p) {
        try {
            String stat = Files.readString(Path.of("/proc/" + p.pid() + "/stat"));
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return Long.parseLong(f[11]) + Long.parseLong(f[12]);
        } catch (IOException | RuntimeException e) {
            return 0;
        }
    }

    private static long rssMb(Process p) {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/" + p.pid() + "/status"))) {
                if (line.startsWith("VmRSS:")) {
                    return Long.parseLong(line.replaceAll("[^0-9]", "")) / 1024;
                }
            }
        } catch (IOException e) {
            // gone
        }
        return -1;
    }

    /** The 16 kHz mono 16-bit PCM of one condition's stream of a voice (the set's WAV files are written so). */
    private static byte[] pcm(EvalSet.Voice v, String condition) throws IOException {
        AudioChunk stream = Utterances.readWav(v.stream(condition));
        if (stream.format().sampleRateHz() != RATE_HZ || stream.format().channels() != 1) {
            throw new IOException(v.stream(condition) + " is not 16 kHz mono");
        }
        return stream.pcm();
    }
}
