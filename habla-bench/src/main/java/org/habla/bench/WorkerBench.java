// Over 300 lines, on purpose: benchmark (e)'s three rows (latency, audio, speech) share one worker set-up per place
// (loopback, another network namespace) and print side by side; a file per row would pass the set-up around.
package org.habla.bench;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import javax.sound.sampled.AudioInputStream;
import javax.sound.sampled.AudioSystem;
import org.HdrHistogram.Histogram;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.net.Frame;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.habla.testing.NetworkNamespace;

/**
 * Benchmark (e): what placing a method on a {@code habla worker} costs. The worker is a JVM of its own
 * ({@code habla worker}), reached over loopback and, where network namespaces can be made (root), from
 * another namespace through a veth pair, as another computer would be.
 * <ul>
 *   <li>latency: the chain of (a) with its processing method placed on the worker, against the same chain
 *       all in the daemon; the difference is what the two crossings (daemon → worker → daemon) add;</li>
 *   <li>audio: 100 ms chunks of 16 kHz mono PCM written into a control socket as fast as the daemon takes
 *       them, through a pass-through placed on the worker and back out of another socket;</li>
 *   <li>speech: the simulator's recorded commands, one utterance at a time, through Speech Recognition in
 *       the daemon and on the worker: the time from handing the segment over to the recognised phrase.</li>
 * </ul>
 */
final class WorkerBench {

    private static final int CHUNK_BYTES = 3_200;
    private static final int WINDOW = 32;

    /** The secret the daemon and its workers share: a worker must have one to listen beyond loopback. */
    private static final String SECRET = "habla-bench-worker-secret-" + Long.toHexString(System.nanoTime());

    private final int rateHz;
    private final int warmupS;
    private final int seconds;
    /** The worker's secret file and the daemon's credentials file holding the same secret, owner-only. */
    private final Path secretFile;
    private final Path credentials;

    WorkerBench(int rateHz, int warmupS, int seconds) {
        this.rateHz = rateHz;
        this.warmupS = warmupS;
        this.seconds = seconds;
        try {
            Path dir = Files.createTempDirectory("habla-bench-worker");
            secretFile = ownerOnly(dir.resolve("worker.secret"), SECRET + "\n");
            credentials = ownerOnly(dir.resolve("credentials.json"), "{\"workerSecret\": \"" + SECRET + "\"}");
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static Path ownerOnly(Path file, String text) throws IOException {
        Files.writeString(file, text);
        Files.setPosixFilePermissions(file, java.nio.file.attribute.PosixFilePermissions.fromString("rw-------"));
        return file;
    }

    /** Where a worker runs: its address, and the command prefix that starts it there. */
    private record Place(String name, String address, List<String> wrapper) {
    }

    void run() throws Exception {
        List<Place> places = new ArrayList<>(List.of(new Place("worker JVM, loopback", "127.0.0.1", List.of())));
        String why = NetworkNamespace.unavailable();
        NetworkNamespace ns = null;
        if (why == null) {
            try {
                ns = NetworkNamespace.create();
                places.add(new Place("worker JVM, other network namespace", ns.address(), ns.wrapper()));
            } catch (IOException e) {
                why = e.getMessage();
            }
        }
        try {
            if (why != null) {
                System.out.println("\n(no network namespace: " + why + ")");
            }
            latency(places);
            audio(places);
            speech(places);
        } finally {
            if (ns != null) {
                ns.close();
            }
        }
    }

    // ------------------------------------------------------------------ latency

    private void latency(List<Place> places) throws Exception {
        System.out.printf("%n(e) remote placement latency, robot stamp -> control client, %d Hz readings, %d s warm-up, "
                + "%d s measured%n", rateHz, warmupS, seconds);
        System.out.printf("%-52s %8s %8s %8s %8s %8s%n", "processing method p", "samples", "lost", "p50 µs", "p99 µs",
                "max µs");
        latencyRow("in the daemon", null);
        for (Place place : places) {
            try (Worker w = Worker.start(place, secretFile)) {
                latencyRow("on a " + place.name(), w.host());
            }
        }
    }

    private void latencyRow(String name, String host) throws Exception {
        try (BenchRobot robot = new BenchRobot(1_000_000_000L / rateHz)) {
            Daemon d = BenchDaemon.start(robot.port(), host, security(host));
            try (SampleClient client = new SampleClient(d.port("value"))) {
                LatencyBench.await(() -> client.total() > 0, 30_000, name + ": no sample reached the client");
                Thread.sleep(warmupS * 1000L);
                client.startRecording();
                Thread.sleep(seconds * 1000L);
                client.stopRecording();
                Histogram h = client.latencyMicros();
                System.out.printf("%-52s %8d %8d %8d %8d %8d%n", name, client.samples(), client.missing(),
                        h.getValueAtPercentile(50), h.getValueAtPercentile(99), h.getMaxValue());
            } finally {
                d.close();
            }
        }
    }

    // ------------------------------------------------------------------ audio throughput

    private void audio(List<Place> places) throws Exception {
        System.out.printf("%n(e) audio to a placed method: 100 ms chunks (%d bytes of 16 kHz mono PCM), at most %d "
                + "unacknowledged writes, %d s%n", CHUNK_BYTES, WINDOW, seconds);
        System.out.printf("%-52s %10s %10s %10s %10s%n", "pass-through p", "chunks/s", "MB/s", "x realtime", "refused");
        audioRow("in the daemon", null);
        for (Place place : places) {
            try (Worker w = Worker.start(place, secretFile)) {
                audioRow("on a " + place.name(), w.host());
            }
        }
    }

    private void audioRow(String name, String host) throws Exception {
        String relay = "\"params\": {\"kind\": \"audio\", \"delivery\": \"queue\", \"capacity\": 1024}";
        int[] ports = DaemonProcess.freePorts(2);
        Daemon d = daemon("""
                {"system": "bench-audio", "status": {"port": 0}, "methods": [
                  {"id": "in", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"}, %s,
                   "expose": {"port": %d, "name": "in"}},
                  {"id": "p", "type": "pass-through", "layer": "processing", "inputs": {"in": "in.out"}, %s%s},
                  {"id": "out", "type": "pass-through", "layer": "virtual", "inputs": {"in": "p.out"}, %s,
                   "expose": {"port": %d, "name": "out"}}]}
                """.formatted(relay, ports[0], relay, hostKey(host), relay, ports[1]));
        try (Socket in = connect(d.port("in")); Socket out = connect(d.port("out"))) {
            AtomicLong received = new AtomicLong();
            Thread reader = Thread.ofPlatform().daemon().start(() -> count(out, received));
            Writer writer = new Writer(in);
            LatencyBench.await(() -> {
                writer.write(new byte[CHUNK_BYTES]);
                return received.get() > 0;
            }, 30_000, name + ": no audio came back");
            long endWarm = System.nanoTime() + warmupS * 1_000_000_000L;
            while (System.nanoTime() < endWarm) {
                writer.write(new byte[CHUNK_BYTES]);
            }
            long before = received.get();
            long refusedBefore = writer.refused.get();
            long start = System.nanoTime();
            long end = start + seconds * 1_000_000_000L;
            while (System.nanoTime() < end) {
                writer.write(new byte[CHUNK_BYTES]);
            }
            double s = (System.nanoTime() - start) / 1e9;
            long n = received.get() - before;
            System.out.printf("%-52s %10.0f %10.2f %10.0f %10d%n", name, n / s, n * CHUNK_BYTES / s / 1e6,
                    n * 0.1 / s, writer.refused.get() - refusedBefore);
            reader.interrupt();
        } finally {
            d.close();
        }
    }

    /** Writes audio into a control socket with ids, keeping at most {@link #WINDOW} unanswered. */
    private static final class Writer {
        private final FrameWriter out;
        private final Semaphore window = new Semaphore(WINDOW);
        private final AtomicLong refused = new AtomicLong();
        private long id;

        Writer(Socket s) throws IOException {
            out = new FrameWriter(s.getOutputStream());
            FrameReader replies = new FrameReader(new BufferedInputStream(s.getInputStream()), 1 << 20, 1 << 20);
            Thread.ofPlatform().daemon().start(() -> {
                try {
                    for (Frame f = replies.read(); f != null; f = replies.read()) {
                        if (f.header().has("id")) {
                            if (f.type().equals("error")) {
                                refused.incrementAndGet();
                            }
                            window.release();
                        }
                    }
                } catch (IOException e) {
                    // the benchmark closed the socket
                }
            });
        }

        void write(byte[] pcm) throws Exception {
            if (!window.tryAcquire(10, TimeUnit.SECONDS)) {
                throw new IOException("no reply to a write for 10 s");
            }
            ObjectNode header = JsonNodeFactory.instance.objectNode().put("op", "write").put("input", "in")
                    .put("id", ++id).put("kind", "audio").put("rateHz", 16_000).put("channels", 1).put("bits", 16);
            out.send(new Frame(header, pcm));
        }
    }

    private static void count(Socket s, AtomicLong received) {
        try {
            FrameReader r = new FrameReader(new BufferedInputStream(s.getInputStream(), 1 << 16), 1 << 20, 1 << 24);
            for (Frame f = r.read(); f != null; f = r.read()) {
                if (f.type().equals("sample")) {
                    received.incrementAndGet();
                }
            }
        } catch (IOException e) {
            // closed
        }
    }

    // ------------------------------------------------------------------ speech

    private void speech(List<Place> places) throws Exception {
        List<byte[]> takes = utterances();
        double audioS = 0;
        for (byte[] t : takes) {
            audioS += t.length / 32_000.0;
        }
        System.out.printf("%n(e) Speech Recognition placed on a worker: %d recorded commands (%.1f s of speech), one at "
                + "a time, segment handed over -> phrase back%n", takes.size(), audioS);
        System.out.printf("%-52s %8s %10s %10s %10s%n", "speech-recognition", "phrases", "p50 ms", "max ms",
                "x realtime");
        speechRow("in the daemon", null, takes);
        for (Place place : places) {
            try (Worker w = Worker.start(place, secretFile)) {
                speechRow("on a " + place.name(), w.host(), takes);
            }
        }
    }

    private void speechRow(String name, String host, List<byte[]> takes) throws Exception {
        int[] ports = DaemonProcess.freePorts(2);
        Daemon d = daemon("""
                {"system": "bench-speech", "status": {"port": 0}, "methods": [
                  {"id": "in", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
                   "params": {"kind": "audio", "delivery": "queue", "capacity": 64}, "expose": {"port": %d, "name": "in"}},
                  {"id": "speech", "type": "speech-recognition", "layer": "processing", "inputs": {"segments": "in.out"}%s},
                  {"id": "out", "type": "pass-through", "layer": "virtual", "inputs": {"in": "speech.words"},
                   "params": {"kind": "text", "delivery": "queue"}, "expose": {"port": %d, "name": "out"}}]}
                """.formatted(ports[0], hostKey(host), ports[1]));
        try (Socket in = connect(d.port("in")); Socket out = connect(d.port("out"))) {
            BlockingQueue<Long> arrivals = new ArrayBlockingQueue<>(1024);
            Thread.ofPlatform().daemon().start(() -> {
                try {
                    FrameReader r = new FrameReader(new BufferedInputStream(out.getInputStream()), 1 << 20, 1 << 24);
                    for (Frame f = r.read(); f != null; f = r.read()) {
                        if (f.type().equals("sample")) {
                            arrivals.offer(System.nanoTime());
                        }
                    }
                } catch (IOException e) {
                    // closed
                }
            });
            Writer writer = new Writer(in);
            // Warm-up: until the model is loaded and the first phrase comes back.
            long until = System.nanoTime() + 120_000_000_000L;
            Long first = null;
            while (first == null && System.nanoTime() < until) {
                writer.write(takes.get(0));
                first = arrivals.poll(3, TimeUnit.SECONDS);
            }
            if (first == null) {
                throw new IOException(name + ": no phrase within 120 s");
            }
            Thread.sleep(500);
            arrivals.clear();
            Histogram h = new Histogram(60_000_000L, 3);
            double audio = 0;
            double busy = 0;
            int phrases = 0;
            for (byte[] take : takes) {
                long t0 = System.nanoTime();
                writer.write(take);
                Long t1 = arrivals.poll(10, TimeUnit.SECONDS);
                if (t1 == null) {
                    continue;
                }
                phrases++;
                long us = (t1 - t0) / 1_000;
                h.recordValue(us);
                busy += us / 1e6;
                audio += take.length / 32_000.0;
            }
            System.out.printf("%-52s %5d/%-2d %10.1f %10.1f %10.1f%n", name, phrases, takes.size(),
                    h.getValueAtPercentile(50) / 1e3, h.getMaxValue() / 1e3, busy == 0 ? 0 : audio / busy);
        } finally {
            d.close();
        }
    }

    /** The simulator's recorded takes of the four commands, as raw 16 kHz mono PCM. */
    private static List<byte[]> utterances() throws Exception {
        Path dir = Path.of("").toAbsolutePath();
        while (!Files.isDirectory(dir.resolve("habla-sim"))) {
            dir = dir.getParent();
        }
        Path utterances = dir.resolve("habla-sim/src/main/resources/utterances");
        List<byte[]> takes = new ArrayList<>();
        for (String line : Files.readAllLines(utterances.resolve("index.txt"))) {
            String[] f = line.split("\t");
            if (f.length == 2 && List.of("go forward", "turn left", "turn right", "go back").contains(f[1])) {
                try (AudioInputStream a = AudioSystem.getAudioInputStream(utterances.resolve(f[0]).toFile())) {
                    takes.add(a.readAllBytes());
                }
            }
        }
        return takes;
    }

    // ------------------------------------------------------------------ plumbing

    private static String hostKey(String host) {
        return host == null ? "" : ", \"host\": \"" + host + "\"";
    }

    /** The config's "security" object for a daemon whose method is placed on {@code host}, or null for none. */
    private String security(String host) {
        return host == null ? null : securityObject();
    }

    /** The config's "security" object that gives the daemon the workers' secret. */
    private String securityObject() {
        return "{\"credentials\": \"" + credentials.toAbsolutePath() + "\"}";
    }

    /** A daemon of {@code json}; one that places a method on a worker proves the workers' secret to it. */
    private Daemon daemon(String json) throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        if (json.contains("\"host\"")) {
            json = "{\"security\": " + securityObject() + ", " + json.strip().substring(1);
        }
        HablaConfig config = new ConfigLoader(registry).parse(json);
        return Daemon.start(config, registry, EngineClock.system());
    }

    private static Socket connect(int port) throws IOException {
        Socket s = new Socket(InetAddress.getLoopbackAddress(), port);
        s.setTcpNoDelay(true);
        s.getInputStream();
        return s;
    }

    /** A {@code habla worker} JVM started for one row. */
    private record Worker(DaemonProcess process, String host) implements AutoCloseable {

        static Worker start(Place place, Path secretFile) throws Exception {
            int port = DaemonProcess.freePorts(1)[0];
            Path log = Files.createTempFile("habla-bench-worker", ".log");
            DaemonProcess p = DaemonProcess.startWrapped(place.wrapper(), log, "--log-level", "warn", "worker",
                    "--port", "" + port, "--bind", place.address(), "--secret-file", secretFile.toString());
            if (!DaemonProcess.awaitPort(place.address(), port, 60_000)) {
                p.close();
                throw new IOException("the worker did not start: " + p.output());
            }
            return new Worker(p, place.address() + ":" + port);
        }

        @Override
        public void close() {
            process.close();
        }
    }
}
