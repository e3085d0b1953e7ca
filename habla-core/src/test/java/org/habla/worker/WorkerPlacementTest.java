package org.habla.worker;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.zip.CRC32;
import org.habla.net.Expose;
import org.habla.config.Fallback;
import org.habla.config.HablaConfig;
import org.habla.net.Limits;
import org.habla.config.MethodConfig;
import org.habla.config.Safety;
import org.habla.config.Source;
import org.habla.config.StatusConfig;
import org.habla.daemon.Daemon;
import org.habla.daemon.PlacementRefusedException;
import org.habla.graph.EngineClock;
import org.habla.graph.MethodGraph;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.net.ControlPoint;
import org.habla.plugin.NoParams;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(60)
class WorkerPlacementTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    /** Chunks of 32 KB that more than fill a silent worker's queue and both socket buffers on loopback. */
    private static final int MAX_CHUNKS = 5_000;
    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
    }

    // ------------------------------------------------------------------ the protocol, raw

    @Test
    void aWorkerSaysHelloWithItsProtocolAndTheTypesItRuns() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.all(), 0);
        try (Socket s = new Socket("127.0.0.1", worker.port())) {
            s.setSoTimeout(15_000);
            JsonNode hello = JSON.readTree(lines(s).readLine());
            assertThat(hello.path("type").asText()).isEqualTo("hello");
            assertThat(hello.path("protocol").asText()).isEqualTo("habla-worker/1");
            assertThat(hello.path("types").toString()).contains("\"scale\"", "\"audio-digest\"");
        }
    }

    @Test
    void aWorkerRefusesATypeItCannotRunWithAnErrorLine() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.audioOnly(), 0);
        try (Socket s = new Socket("127.0.0.1", worker.port())) {
            s.setSoTimeout(15_000);
            BufferedReader in = lines(s);
            in.readLine();
            send(s, "{\"type\":\"place\",\"method\":\"m\",\"methodType\":\"scale\",\"layer\":\"processing\","
                    + "\"params\":{\"factor\":2}}\n");
            JsonNode error = JSON.readTree(in.readLine());
            assertThat(error.path("type").asText()).isEqualTo("error");
            assertThat(error.path("code").asText()).isEqualTo("unknown_type");
            assertThat(error.path("message").asText()).contains("'scale'");
            assertThat(in.readLine()).as("the worker closes after refusing").isNull();
        }
    }

    @Test
    void audioCrossesAsABinaryBlockAndABadLineCostsOnlyThatLine() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.all(), 0);
        try (Socket s = new Socket("127.0.0.1", worker.port())) {
            s.setSoTimeout(15_000);
            BufferedReader in = lines(s);
            in.readLine();
            send(s, "{\"type\":\"place\",\"method\":\"d\",\"methodType\":\"audio-digest\",\"layer\":\"processing\"}\n");
            JsonNode placed = JSON.readTree(in.readLine());
            assertThat(placed.path("type").asText()).isEqualTo("placed");
            assertThat(placed.path("inputs").toString()).isEqualTo("[\"audio\"]");
            send(s, "{this is not json\n");
            byte[] pcm = pcm(3_200);
            OutputStream out = s.getOutputStream();
            out.write(("{\"type\":\"sample\",\"input\":\"audio\",\"seq\":1,\"t\":5,\"kind\":\"audio\",\"rateHz\":16000,"
                    + "\"channels\":1,\"bits\":16,\"bytes\":" + pcm.length + "}\n").getBytes(StandardCharsets.UTF_8));
            out.write(pcm);
            out.flush();
            List<JsonNode> got = new ArrayList<>();
            while (got.stream().noneMatch(n -> n.path("type").asText().equals("sample"))) {
                JsonNode n = JSON.readTree(in.readLine());
                if (!n.path("type").asText().equals("heartbeat")) {
                    got.add(n);
                }
            }
            assertThat(got.get(0).path("code").asText()).isEqualTo("bad_json");
            JsonNode sample = got.get(got.size() - 1);
            assertThat(sample.path("output").asText()).isEqualTo("digest");
            assertThat(sample.path("t").asLong()).as("the daemon's source time comes back").isEqualTo(5);
            assertThat(sample.path("value").asText()).isEqualTo(pcm.length + " " + crc(pcm) + " 16000");
        }
    }

    @Test
    void aPlacedMethodSeesTheMetadataOfTheInterfaceChannelItsInputReads() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.all(), 0);
        try (Socket s = new Socket("127.0.0.1", worker.port())) {
            s.setSoTimeout(15_000);
            BufferedReader in = lines(s);
            in.readLine();
            send(s, "{\"type\":\"place\",\"method\":\"e\",\"methodType\":\"channel-echo\",\"layer\":\"processing\","
                    + "\"channels\":{\"in\":{\"name\":\"sonar\",\"direction\":\"reading\",\"kind\":\"vector\","
                    + "\"unit\":\"m\",\"motion\":false,\"metadata\":{\"maxRangeM\":5.0}}}}\n");
            assertThat(JSON.readTree(in.readLine()).path("type").asText()).isEqualTo("placed");
            send(s, "{\"type\":\"sample\",\"input\":\"in\",\"seq\":1,\"t\":1,\"kind\":\"number\",\"value\":1}\n");
            JsonNode n;
            do {
                n = JSON.readTree(in.readLine());
            } while (!n.path("type").asText().equals("sample"));
            assertThat(n.path("value").asText()).isEqualTo("sonar m {\"maxRangeM\":5.0}");
        }
    }

    @Test
    void aPlaceLineWithABadChannelIsRefusedNamingThePort() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.all(), 0);
        try (Socket s = new Socket("127.0.0.1", worker.port())) {
            s.setSoTimeout(15_000);
            BufferedReader in = lines(s);
            in.readLine();
            send(s, "{\"type\":\"place\",\"method\":\"e\",\"methodType\":\"channel-echo\",\"layer\":\"processing\","
                    + "\"channels\":{\"in\":{\"name\":\"sonar\",\"direction\":\"sideways\",\"kind\":\"vector\"}}}\n");
            JsonNode error = JSON.readTree(in.readLine());
            assertThat(error.path("code").asText()).isEqualTo("bad_place");
            assertThat(error.path("message").asText()).startsWith("channel of port 'in': ");
        }
    }

    // ------------------------------------------------------------------ the daemon's side

    @Test
    void theDaemonRefusesToStartWhenAWorkerCannotRunAMethodPlacedOnIt() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.audioOnly(), 0);
        HablaConfig cfg = config(numbersOnFreePorts("127.0.0.1:" + worker.port(), Fallback.NONE));
        assertThatThrownBy(() -> Daemon.start(cfg, WorkerTestMethods.all(), EngineClock.system()))
                .isInstanceOf(PlacementRefusedException.class)
                .hasMessageContaining("method 'p' is placed on worker 127.0.0.1:" + worker.port())
                .hasMessageContaining("cannot run method type 'scale' (it runs: audio-digest)");
    }

    @Test
    void theDaemonRefusesAWorkerOfAnotherProtocolVersion() throws Exception {
        try (ServerSocket fake = new ServerSocket(0, 50, java.net.InetAddress.getLoopbackAddress())) {
            Thread.ofVirtual().start(() -> {
                while (!fake.isClosed()) {
                    try (Socket s = fake.accept()) {
                        send(s, "{\"type\":\"hello\",\"protocol\":\"habla-worker/2\",\"types\":[\"scale\"]}\n");
                    } catch (Exception e) {
                        return;
                    }
                }
            });
            HablaConfig cfg = config(numbersOnFreePorts("127.0.0.1:" + fake.getLocalPort(), Fallback.LOCAL));
            assertThatThrownBy(() -> Daemon.start(cfg, WorkerTestMethods.all(), EngineClock.system()))
                    .isInstanceOf(PlacementRefusedException.class)
                    .hasMessageEndingWith("but the worker speaks habla-worker/2, this daemon habla-worker/1");
        }
    }

    @Test
    void numbersGoToTheWorkerAndComeBackWithTheParamsApplied() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.all(), 0);
        MethodGraph g = graph(config(numbers("127.0.0.1:" + worker.port(), Fallback.NONE)));
        BlockingQueue<Sample> seen = listen(point(g, "out"));
        await(() -> placement(g).path("up").asBoolean(), "the placement comes up");
        write(g, new NumberValue(21));
        Sample s = seen.poll(15, TimeUnit.SECONDS);
        assertThat(s).isNotNull();
        assertThat(s.payload()).isEqualTo(new NumberValue(63));
        assertThat(s.stale()).isFalse();
        assertThat(placement(g).path("received").asLong()).isEqualTo(1);
        assertThat(worker.sessions()).isEqualTo(1);
        await(() -> method(g, "p").path("ready").asBoolean(), "the worker's heartbeat says the method is ready");
    }

    @Test
    void audioGoesToARemoteMethodAsBinaryAndItsAnswerComesBack() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.all(), 0);
        MethodGraph g = graph(config(
                method("in", "audio-source", Layer.VIRTUAL, Map.of("in", new Source.Control()), 7001),
                placed("d", "audio-digest", Map.of("audio", out("in")), new NoParams(), "127.0.0.1:" + worker.port(),
                        Fallback.NONE),
                method("out", "text-sink", Layer.VIRTUAL, Map.of("in", new Source.MethodOutput("d", "digest")), 7002)));
        BlockingQueue<Sample> seen = listen(point(g, "out"));
        await(() -> method(g, "d").path("placement").path("up").asBoolean(), "the placement comes up");
        byte[] pcm = pcm(32_000);
        write(g, AudioChunk.of(AudioFormat.MONO_16K, pcm));
        Sample s = seen.poll(15, TimeUnit.SECONDS);
        assertThat(s).isNotNull();
        assertThat(s.payload()).isEqualTo(new TextValue(pcm.length + " " + crc(pcm) + " 16000"));
    }

    @Test
    void aWorkerThatStopsReadingCostsDroppedSamplesOnlyAndTheRestOfTheGraphGoesOn() throws Exception {
        try (ServerSocket fake = new ServerSocket(0, 50, java.net.InetAddress.getLoopbackAddress())) {
            // Says hello, places the method, sends heartbeats, and never reads a byte.
            Thread.ofVirtual().start(() -> {
                try (Socket s = fake.accept()) {
                    send(s, "{\"type\":\"hello\",\"protocol\":\"habla-worker/1\",\"types\":[\"audio-digest\"]}\n");
                    send(s, "{\"type\":\"placed\",\"method\":\"d\",\"inputs\":[\"audio\"],\"outputs\":[\"digest\"]}\n");
                    while (!fake.isClosed()) {
                        send(s, "{\"type\":\"heartbeat\",\"ready\":true,\"readiness\":\"\"}\n");
                        Thread.sleep(300);
                    }
                } catch (Exception e) {
                    // the test is over
                }
            });
            MethodGraph g = graph(config(
                    method("in", "audio-source", Layer.VIRTUAL, Map.of("in", new Source.Control()), 7001),
                    placed("d", "audio-digest", Map.of("audio", out("in")), new NoParams(),
                            "127.0.0.1:" + fake.getLocalPort(), Fallback.NONE),
                    new MethodConfig("here", "audio-digest", Layer.PROCESSING, Map.of("audio", out("in")), Map.of(),
                            new NoParams(), Optional.empty(), Optional.empty()),
                    method("out", "text-sink", Layer.VIRTUAL, Map.of("in", new Source.MethodOutput("here", "digest")),
                            7002)));
            BlockingQueue<Sample> local = listen(point(g, "out"));
            await(() -> method(g, "d").path("placement").path("up").asBoolean(), "the placement comes up");
            // Each chunk is written once the local branch has digested the one before, so the local branch never
            // has to drop; the writes go on until the silent worker's queue and socket buffers are full and the
            // placement drops (a few hundred chunks of 32 KB on loopback).
            byte[] pcm = pcm(32_000);
            int written = 0;
            while (method(g, "d").path("placement").path("dropped").asLong() == 0) {
                assertThat(written).as("the placement drops before %d chunks", MAX_CHUNKS).isLessThan(MAX_CHUNKS);
                write(g, AudioChunk.of(AudioFormat.MONO_16K, pcm));
                written++;
                Sample s = local.poll(10, TimeUnit.SECONDS);
                assertThat(s).as("chunk %d digested by the local branch", written).isNotNull();
                assertThat(s.payload()).isEqualTo(new TextValue(pcm.length + " " + crc(pcm) + " 16000"));
            }
            assertThat(method(g, "d").path("placement").path("up").asBoolean()).as("heartbeats keep it up").isTrue();
        }
    }

    @Test
    void aLostWorkerMakesTheOutputsStaleUntilTheDaemonReconnects() throws Exception {
        int port = freePort();
        WorkerServer worker = worker(WorkerTestMethods.all(), port);
        MethodGraph g = graph(config(numbers("127.0.0.1:" + port, Fallback.NONE)));
        BlockingQueue<Sample> seen = new LinkedBlockingQueue<>();
        BlockingQueue<String> staleness = new LinkedBlockingQueue<>();
        point(g, "out").subscribe(listener(seen, staleness));
        await(() -> placement(g).path("up").asBoolean(), "the placement comes up");
        assertThat(method(g, "out").path("stale").asBoolean()).isFalse();

        worker.close();
        await(() -> !placement(g).path("up").asBoolean(), "the placement notices the lost worker");
        assertThat(next(staleness, "stale")).isEqualTo("stale: worker 127.0.0.1:" + port + " of method p is lost");
        assertThat(method(g, "p").path("stale").asBoolean()).isTrue();
        assertThat(method(g, "p").path("ready").asBoolean()).isFalse();
        assertThat(method(g, "p").path("readiness").asText()).isEqualTo("worker 127.0.0.1:" + port + " is lost");
        assertThat(method(g, "out").path("stale").asBoolean()).as("what depends on it is stale too").isTrue();
        write(g, new NumberValue(1));
        await(() -> placement(g).path("dropped").asLong() >= 1, "a sample with nowhere to go is counted");
        assertThat(seen.poll(300, TimeUnit.MILLISECONDS)).isNull();

        worker(WorkerTestMethods.all(), port);
        await(() -> placement(g).path("up").asBoolean(), "the daemon reconnects");
        assertThat(next(staleness, "fresh")).isEqualTo("fresh: all links up");
        assertThat(placement(g).path("connects").asLong()).isEqualTo(2);
        write(g, new NumberValue(2));
        Sample s = seen.poll(15, TimeUnit.SECONDS);
        assertThat(s).isNotNull();
        assertThat(s.payload()).isEqualTo(new NumberValue(6));
        assertThat(s.stale()).isFalse();
    }

    @Test
    void withALocalFallbackTheMethodRunsInTheDaemonWhileItsWorkerIsAway() throws Exception {
        int port = freePort();
        MethodGraph g = graph(config(numbers("127.0.0.1:" + port, Fallback.LOCAL)));
        BlockingQueue<Sample> seen = listen(point(g, "out"));
        await(() -> placement(g).path("failures").asLong() >= 1, "the first connect fails");
        write(g, new NumberValue(5));
        Sample local = seen.poll(15, TimeUnit.SECONDS);
        assertThat(local).isNotNull();
        assertThat(local.payload()).isEqualTo(new NumberValue(15));
        assertThat(local.stale()).as("the fallback's outputs are fresh").isFalse();
        assertThat(placement(g).path("received").asLong()).isZero();

        WorkerServer worker = worker(WorkerTestMethods.all(), port);
        await(() -> placement(g).path("up").asBoolean(), "the daemon reaches the worker");
        write(g, new NumberValue(7));
        Sample remote = seen.poll(15, TimeUnit.SECONDS);
        assertThat(remote).isNotNull();
        assertThat(remote.payload()).isEqualTo(new NumberValue(21));
        assertThat(placement(g).path("received").asLong()).as("now the worker computes it").isEqualTo(1);
        assertThat(worker.sessions()).isEqualTo(1);
    }

    // ------------------------------------------------------------------ set-up

    // ------------------------------------------------------------------ the shared secret

    private static final String SECRET = "the-lab-worker-secret-0123";

    @Test
    void anUntrustedDaemonCannotPlaceAMethodAndATrustedOneCan() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.all(), 0, org.habla.security.WorkerSecret.of(SECRET));
        String host = "127.0.0.1:" + worker.port();
        MethodGraph untrusted = graph(secured("not-the-lab-secret-0123", numbers(host, Fallback.NONE)));
        await(() -> placement(untrusted).path("lastError").asText().contains("does not trust this daemon"),
                "the worker refuses the daemon with the wrong secret");
        assertThat(placement(untrusted).path("up").asBoolean()).isFalse();
        assertThat(worker.authFailures()).isPositive();
        untrusted.close();

        MethodGraph trusted = graph(secured(SECRET, numbers(host, Fallback.NONE)));
        BlockingQueue<Sample> seen = listen(point(trusted, "out"));
        await(() -> placement(trusted).path("up").asBoolean(), "the trusted daemon's placement comes up");
        write(trusted, new NumberValue(2));
        Sample s = seen.poll(15, TimeUnit.SECONDS);
        assertThat(s).isNotNull();
        assertThat(s.payload()).isEqualTo(new NumberValue(6));
    }

    @Test
    void theDaemonRefusesToStartWhenAWorkerAtStartDoesNotTrustItsSecret() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.all(), 0, org.habla.security.WorkerSecret.of(SECRET));
        String host = "127.0.0.1:" + worker.port();
        HablaConfig wrong = secured("not-the-lab-secret-0123", numbersOnFreePorts(host, Fallback.NONE));
        assertThatThrownBy(() -> Daemon.start(wrong, WorkerTestMethods.all(), EngineClock.system()))
                .isInstanceOf(PlacementRefusedException.class)
                .hasMessageContaining("method 'p' is placed on worker " + host)
                .hasMessageContaining("does not trust this daemon");

        try (Daemon right = Daemon.start(secured(SECRET, numbersOnFreePorts(host, Fallback.NONE)),
                WorkerTestMethods.all(), EngineClock.system())) {
            await(() -> right.status().path("methods").findValues("placement").stream()
                    .anyMatch(p -> p.path("up").asBoolean()), "the placement of a daemon with the secret comes up");
        }
    }

    @Test
    void aWorkerFullOfMethodsAtStartDoesNotStopTheDaemonItTrusts() throws Exception {
        EngineClock clock = EngineClock.system();
        toClose.add(clock::close);
        WorkerServer worker = new WorkerServer(WorkerTestMethods.all(), "127.0.0.1", 0, clock,
                WorkerCommand.limits(1), org.habla.security.WorkerSecret.of(SECRET), null);
        toClose.add(worker);
        worker.start();
        String host = "127.0.0.1:" + worker.port();
        MethodGraph first = graph(secured(SECRET, numbers(host, Fallback.NONE)));
        await(() -> placement(first).path("up").asBoolean(), "the first daemon's placement takes the only place");

        try (Daemon second = Daemon.start(secured(SECRET, numbersOnFreePorts(host, Fallback.LOCAL)),
                WorkerTestMethods.all(), EngineClock.system())) {
            await(() -> second.status().path("methods").findValues("placement").stream()
                    .anyMatch(p -> p.path("lastError").asText().contains("--max-methods=1")),
                    "the second daemon runs, its placement down with the worker's reason");
        }
    }

    @Test
    void aWorkerWithASecretRefusesAPlaceLineThatCameWithoutTheProof() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.all(), 0, org.habla.security.WorkerSecret.of(SECRET));
        try (Socket s = new Socket("127.0.0.1", worker.port())) {
            s.setSoTimeout(15_000);
            BufferedReader in = lines(s);
            JsonNode hello = JSON.readTree(in.readLine());
            assertThat(hello.path("auth").asText()).isEqualTo("required");
            assertThat(hello.path("challenge").asText()).hasSizeGreaterThan(40);
            send(s, "{\"type\":\"place\",\"method\":\"p\",\"methodType\":\"scale\",\"layer\":\"processing\","
                    + "\"params\":{\"factor\":3},\"channels\":{},\"commandChannels\":{}}\n");
            JsonNode answer = JSON.readTree(in.readLine());
            assertThat(answer.path("code").asText()).isEqualTo("auth_failed");
            assertThat(in.readLine()).as("the worker closes without placing anything").isNull();
        }
        assertThat(worker.authFailures()).isEqualTo(1);
    }

    @Test
    void aDaemonWithASecretDoesNotTrustAWorkerThatCannotProveIt() throws Exception {
        WorkerServer worker = worker(WorkerTestMethods.all(), 0);
        MethodGraph g = graph(secured(SECRET, numbers("127.0.0.1:" + worker.port(), Fallback.NONE)));
        await(() -> placement(g).path("lastError").asText().contains("does not ask for the shared secret"),
                "the daemon refuses a worker that asks for no secret");
        assertThat(placement(g).path("up").asBoolean()).isFalse();
    }

    @Test
    void theWorkerCommandRefusesToListenBeyondLoopbackWithoutASecret() {
        java.io.StringWriter err = new java.io.StringWriter();
        int code = new picocli.CommandLine(new WorkerCommand()).setErr(new java.io.PrintWriter(err))
                .execute("--bind", "0.0.0.0", "--port", "0");
        assertThat(code).isEqualTo(org.habla.command.ExitCodes.USAGE_OR_CONFIG);
        assertThat(err.toString()).contains("--bind 0.0.0.0 is beyond loopback", "--secret-file");
    }

    @Test
    void aWorkerAskedForEveryIpv4AddressDoesNotListenOnIpv6() throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue(org.habla.testing.DaemonProcess.ipv6Loopback(),
                "this computer has no IPv6 loopback");
        EngineClock clock = EngineClock.system();
        toClose.add(clock::close);
        WorkerServer worker = new WorkerServer(WorkerTestMethods.all(), "0.0.0.0", 0, clock, Limits.DEFAULTS,
                org.habla.security.WorkerSecret.of(SECRET), null);
        toClose.add(worker);
        worker.start();
        try (Socket v4 = new Socket("127.0.0.1", worker.port())) {
            v4.setSoTimeout(15_000);
            assertThat(JSON.readTree(lines(v4).readLine()).path("type").asText()).isEqualTo("hello");
        }
        assertThatThrownBy(() -> new Socket("::1", worker.port()).close()).isInstanceOf(java.net.ConnectException.class);
    }

    @Test
    void aDaemonTrustingTheWorkersCertificatePlacesOverTlsAndAPlainDaemonIsToldWhy(@org.junit.jupiter.api.io.TempDir
            java.nio.file.Path dir) throws Exception {
        java.nio.file.Path cert = dir.resolve("worker.crt");
        java.nio.file.Path key = dir.resolve("worker.key");
        Process p = new ProcessBuilder("openssl", "req", "-x509", "-newkey", "ec", "-pkeyopt",
                "ec_paramgen_curve:prime256v1", "-nodes", "-keyout", key.toString(), "-out", cert.toString(), "-days",
                "2", "-subj", "/CN=localhost", "-addext", "subjectAltName=IP:127.0.0.1").redirectErrorStream(true)
                .start();
        String made = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0).as("openssl: %s", made).isTrue();
        EngineClock clock = EngineClock.system();
        WorkerServer worker = new WorkerServer(WorkerTestMethods.all(), "127.0.0.1", 0, clock, Limits.DEFAULTS,
                org.habla.security.WorkerSecret.of(SECRET), org.habla.security.Tls.server(cert, key));
        toClose.add(clock::close);
        toClose.add(worker);
        worker.start();
        String host = "127.0.0.1:" + worker.port();

        MethodGraph plain = graph(secured(SECRET, numbers(host, Fallback.NONE)));
        await(() -> placement(plain).path("lastError").asText().contains("tls_required"),
                "a daemon that speaks plain TCP to a TLS worker is told so");
        plain.close();

        var credentials = org.habla.security.Credentials.of(Map.of(), SECRET);
        MethodGraph overTls = graph(new HablaConfig("worker-test", Limits.DEFAULTS, new Safety(0),
                new StatusConfig("127.0.0.1", 0), List.of(), List.of(numbers(host, Fallback.NONE)), List.of(),
                new org.habla.config.SecurityConfig(null, credentials, null, false, false, null, null, cert)));
        BlockingQueue<Sample> seen = listen(point(overTls, "out"));
        await(() -> placement(overTls).path("up").asBoolean(), "the placement comes up over TLS");
        write(overTls, new NumberValue(5));
        Sample s = seen.poll(15, TimeUnit.SECONDS);
        assertThat(s).isNotNull();
        assertThat(s.payload()).isEqualTo(new NumberValue(15));
    }

    private static HablaConfig secured(String workerSecret, MethodConfig... methods) {
        var credentials = org.habla.security.Credentials.of(Map.of(), workerSecret);
        return new HablaConfig("worker-test", Limits.DEFAULTS, new Safety(0), new StatusConfig("127.0.0.1", 0),
                List.of(), List.of(methods), List.of(), new org.habla.config.SecurityConfig(null, credentials, null,
                        false, false, null, null, null));
    }

    private WorkerServer worker(PluginRegistry registry, int port, org.habla.security.WorkerSecret secret)
            throws Exception {
        EngineClock clock = EngineClock.system();
        WorkerServer w = new WorkerServer(registry, "127.0.0.1", port, clock, Limits.DEFAULTS, secret, null);
        toClose.add(clock::close);
        toClose.add(w);
        w.start();
        return w;
    }

    private WorkerServer worker(PluginRegistry registry, int port) throws Exception {
        EngineClock clock = EngineClock.system();
        WorkerServer w = new WorkerServer(registry, "127.0.0.1", port, clock, Limits.DEFAULTS);
        toClose.add(clock::close);
        toClose.add(w);
        w.start();
        return w;
    }

    private MethodGraph graph(HablaConfig config) {
        MethodGraph g = MethodGraph.build(config, WorkerTestMethods.all(), EngineClock.system());
        toClose.add(g);
        g.start();
        return g;
    }

    /** in (control) → p (scale ×3, on a worker) → out (exposed). */
    private static MethodConfig[] numbers(String host, Fallback fallback) {
        return numbers(host, fallback, 7001, 7002);
    }

    /** The same with the sockets on free ports, for a whole daemon, which binds them (7001 may be a daemon's). */
    private static MethodConfig[] numbersOnFreePorts(String host, Fallback fallback) throws java.io.IOException {
        int[] free = org.habla.testing.DaemonProcess.freePorts(2);
        return numbers(host, fallback, free[0], free[1]);
    }

    private static MethodConfig[] numbers(String host, Fallback fallback, int inPort, int outPort) {
        return new MethodConfig[] {
            method("in", "number-source", Layer.VIRTUAL, Map.of("in", new Source.Control()), inPort),
            placed("p", "scale", Map.of("in", out("in")), new WorkerTestMethods.ScaleParams(3), host, fallback),
            method("out", "number-sink", Layer.VIRTUAL, Map.of("in", new Source.MethodOutput("p", "out")), outPort)};
    }

    private static Source out(String id) {
        return new Source.MethodOutput(id, "out");
    }

    private static MethodConfig method(String id, String type, Layer layer, Map<String, Source> inputs, int port) {
        return new MethodConfig(id, type, layer, inputs, Map.of(), new NoParams(),
                Optional.of(new Expose(id, "127.0.0.1", port)), Optional.empty());
    }

    private static MethodConfig placed(String id, String type, Map<String, Source> inputs, Record params, String host,
            Fallback fallback) {
        return new MethodConfig(id, type, Layer.PROCESSING, inputs, Map.of(), params, Optional.empty(),
                Optional.of(host), fallback);
    }

    private static HablaConfig config(MethodConfig... methods) {
        return new HablaConfig("worker-test", Limits.DEFAULTS, new Safety(0), new StatusConfig("127.0.0.1", 0),
                List.of(), List.of(methods));
    }

    private static ControlPoint point(MethodGraph g, String name) {
        return g.controlPoints().stream().filter(p -> p.name().equals(name)).findFirst().orElseThrow();
    }

    private static void write(MethodGraph g, org.habla.sample.Payload value) throws ControlPoint.Rejected {
        ControlPoint in = point(g, "in");
        in.write(in.controlInputs().get(0), value);
    }

    private static JsonNode method(MethodGraph g, String id) {
        for (JsonNode m : g.status().path("methods")) {
            if (m.path("id").asText().equals(id)) {
                return m;
            }
        }
        throw new AssertionError("no method " + id);
    }

    private static JsonNode placement(MethodGraph g) {
        return method(g, "p").path("placement");
    }

    private static ControlPoint.Listener listener(BlockingQueue<Sample> samples, BlockingQueue<String> staleness) {
        return new ControlPoint.Listener() {
            @Override
            public void onSample(Output<?> output, Sample sample) {
                samples.add(sample);
            }

            @Override
            public void onStale(boolean stale, String why) {
                staleness.add((stale ? "stale: " : "fresh: ") + why);
            }
        };
    }

    private static BlockingQueue<Sample> listen(ControlPoint p) {
        BlockingQueue<Sample> q = new LinkedBlockingQueue<>();
        p.subscribe(listener(q, new LinkedBlockingQueue<>()));
        return q;
    }

    private static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > end) {
                throw new AssertionError("timed out waiting until " + what);
            }
            Thread.sleep(20);
        }
    }

    /** The next notice starting with {@code prefix}, skipping others; fails after 15 s. */
    private static String next(BlockingQueue<String> notices, String prefix) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
        while (System.nanoTime() < end) {
            String n = notices.poll(100, TimeUnit.MILLISECONDS);
            if (n != null && n.startsWith(prefix)) {
                return n;
            }
        }
        throw new AssertionError("no '" + prefix + "' notice within 15 s");
    }

    private static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    private static BufferedReader lines(Socket s) throws Exception {
        return new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8));
    }

    private static void send(Socket s, String text) throws Exception {
        s.getOutputStream().write(text.getBytes(StandardCharsets.UTF_8));
        s.getOutputStream().flush();
    }

    private static byte[] pcm(int bytes) {
        byte[] b = new byte[bytes];
        for (int i = 0; i < bytes; i++) {
            b[i] = (byte) (i * 31 + (i >> 7));
        }
        b[0] = '\n';
        b[1] = '{';
        return b;
    }

    private static String crc(byte[] b) {
        CRC32 c = new CRC32();
        c.update(b);
        return Long.toHexString(c.getValue());
    }
}
