package org.habla.sim.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.habla.sim.scenario.TruthLink;
import org.habla.testing.DaemonProcess;
import org.habla.testing.NetworkNamespace;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The Aibo set-up with its Speech Recognition on a worker, every part in a process of its own as on the
 * paper's separate computers: the simulated Aibo, {@code habla worker}, the daemon with config/aibo.json
 * whose {@code speech} method says {@code "host"}, and a Python control client. A spoken command must
 * still reach the command socket, recognised by the worker. The second test puts the worker in a network
 * namespace of its own with its own address (a veth pair), so the daemon reaches it as another computer.
 * Both workers hold a secret, as they must beyond loopback: the daemon proves it and places its method; a
 * daemon with a wrong proof is refused and places nothing. The daemon's {@code distance_angle} socket speaks
 * TLS with a lab certificate made by {@code openssl}: a Python client with {@code ssl} reads it, a plain one is
 * told {@code tls_required}.
 */
@Timeout(300)
class WorkerEndToEndTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @Test
    void aSpokenCommandReachesTheCommandSocketWhenSpeechRecognitionRunsOnAWorker() throws Exception {
        Path dir = Files.createDirectories(Path.of("target/e2e/worker"));
        spokenCommandThroughAWorker(dir, List.of(), "127.0.0.1");
    }

    @Test
    void theSameWorksWithTheWorkerInANetworkNamespaceOfItsOwn() throws Exception {
        String why = NetworkNamespace.unavailable();
        if (why != null) {
            Assumptions.abort("skipped: " + why);
        }
        Path dir = Files.createDirectories(Path.of("target/e2e/worker-netns"));
        NetworkNamespace ns;
        try {
            ns = NetworkNamespace.create();
        } catch (IOException e) {
            Assumptions.abort("skipped: cannot make a network namespace with a veth pair: " + e.getMessage());
            return;
        }
        try (ns) {
            spokenCommandThroughAWorker(dir, ns.wrapper(), ns.address());
        }
    }

    /** Runs the worker (under {@code wrapper}, listening on {@code address}), the sim, the daemon and a client. */
    private static void spokenCommandThroughAWorker(Path dir, List<String> wrapper, String address) throws Exception {
        int workerPort = DaemonProcess.freePorts(1)[0];
        String host = address + ":" + workerPort;
        Path secretFile = ownerOnly(dir.resolve("worker.secret"), SECRET + "\n");
        Path credentials = ownerOnly(dir.resolve("lab.credentials.json"), "{\"workerSecret\": \"" + SECRET + "\"}");
        Path certificate = labCertificate(dir);
        try (DaemonProcess worker = DaemonProcess.startWrapped(wrapper, dir.resolve("worker.log"), "worker",
                "--port", "" + workerPort, "--bind", address, "--secret-file", secretFile.toString());
             SimulatedDeployment rig = new SimulatedDeployment("aibo", "aibo-arena", 1, dir, c -> {
                 placeSpeech(c, host);
                 ObjectNode security = c.putObject("security").put("credentials", credentials.toAbsolutePath().toString());
                 security.putObject("tls").put("certificate", certificate.toAbsolutePath().toString())
                         .put("key", dir.resolve("lab.key").toAbsolutePath().toString());
                 for (JsonNode m : c.path("methods")) {
                     if (m.path("expose").path("name").asText().equals("distance_angle")) {
                         ((ObjectNode) m.path("expose")).put("tls", true);
                     }
                 }
             })) {
            assertThat(DaemonProcess.awaitPort(address, workerPort, 60_000)).as("worker up; log: %s", worker.output())
                    .isTrue();
            rig.startSimulator();
            rig.startDaemon();
            rig.awaitReady(120_000);

            Process client = rig.probeAsync("first", "" + rig.port("command"), "30");
            try (BufferedReader out = new BufferedReader(new InputStreamReader(client.getInputStream(),
                    StandardCharsets.UTF_8))) {
                assertThat(out.readLine()).contains("ready");
                rig.truth.send(TruthLink.op("say").put("label", "left"));
                JsonNode got = JSON.readTree(out.readLine());
                assertThat(got.path("value").asText()).as("daemon log: %s", rig.daemon.output()).isEqualTo("left");
            } finally {
                client.waitFor(5, TimeUnit.SECONDS);
                client.destroyForcibly();
            }

            JsonNode speech = method(status(rig), "speech");
            assertThat(speech.path("placement").path("host").asText()).isEqualTo(host);
            assertThat(speech.path("placement").path("up").asBoolean()).isTrue();
            assertThat(speech.path("placement").path("sent").asLong()).as("audio segments went to the worker")
                    .isPositive();
            assertThat(speech.path("placement").path("received").asLong()).as("words came back").isPositive();
            assertThat(worker.output()).contains("running method speech");

            try (Socket untrusted = new Socket(address, workerPort)) {
                untrusted.setSoTimeout(15_000);
                BufferedReader in = new BufferedReader(new InputStreamReader(untrusted.getInputStream(),
                        StandardCharsets.UTF_8));
                assertThat(JSON.readTree(in.readLine()).path("auth").asText()).isEqualTo("required");
                untrusted.getOutputStream().write(("{\"type\":\"auth\",\"challenge\":\"bm9uY2U=\","
                        + "\"proof\":\"bm90LXRoZS1wcm9vZg==\"}\n").getBytes(StandardCharsets.UTF_8));
                assertThat(JSON.readTree(in.readLine()).path("code").asText()).isEqualTo("auth_failed");
                assertThat(in.readLine()).as("an untrusted daemon places nothing").isNull();
            }
            assertThat(worker.output()).contains("did not prove the shared secret");

            readDistanceAngleOverTls(rig, certificate);
        }
    }

    /** A Python client with ssl reads distance_angle from its TLS socket; a plain client is told, not left waiting. */
    private static void readDistanceAngleOverTls(SimulatedDeployment rig, Path certificate) throws Exception {
        int port = rig.port("distance_angle");
        String script = """
                import json, sys
                import habla
                with habla.connect("127.0.0.1", int(sys.argv[1]), tls=sys.argv[2], timeout=30) as s:
                    print(s._sock.version(), s.hello.socket)
                    print(json.dumps(s.next_sample(timeout=30).line))
                """;
        ProcessBuilder pb = new ProcessBuilder("python3", "-c", script, "" + port, certificate.toString())
                .redirectErrorStream(true);
        pb.environment().put("PYTHONPATH", SimulatedDeployment.HOME.resolve("clients/python/src").toString());
        Process p = pb.start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as("python: %s", out).isZero();
        List<String> lines = out.lines().toList();
        assertThat(lines.get(0)).isEqualTo("TLSv1.3 distance_angle");
        JsonNode sample = JSON.readTree(lines.get(1));
        assertThat(sample.path("type").asText()).isEqualTo("sample");
        assertThat(sample.path("kind").asText()).isEqualTo("record");

        try (Socket plain = new Socket("127.0.0.1", port)) {
            plain.setSoTimeout(15_000);
            BufferedReader in = new BufferedReader(new InputStreamReader(plain.getInputStream(), StandardCharsets.UTF_8));
            assertThat(JSON.readTree(in.readLine()).path("code").asText()).isEqualTo("tls_required");
            assertThat(in.readLine()).as("then the daemon closes").isNull();
        }
    }

    /** A lab certificate for 127.0.0.1 and its key, made as docs/security.md says. */
    private static Path labCertificate(Path dir) throws Exception {
        Path cert = dir.resolve("lab.crt");
        Path key = dir.resolve("lab.key");
        Files.deleteIfExists(cert);
        Files.deleteIfExists(key);
        Process p = new ProcessBuilder("openssl", "req", "-x509", "-newkey", "ec", "-pkeyopt",
                "ec_paramgen_curve:prime256v1", "-nodes", "-keyout", key.toString(), "-out", cert.toString(), "-days",
                "2", "-subj", "/CN=localhost", "-addext", "subjectAltName=IP:127.0.0.1").redirectErrorStream(true)
                .start();
        String made = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0).as("openssl: %s", made).isTrue();
        return cert;
    }

    private static final String SECRET = "a-lab-worker-secret-for-the-test";

    private static Path ownerOnly(Path file, String text) throws IOException {
        Files.deleteIfExists(file);
        Files.createFile(file, java.nio.file.attribute.PosixFilePermissions.asFileAttribute(
                java.nio.file.attribute.PosixFilePermissions.fromString("rw-------")));
        Files.writeString(file, text);
        return file;
    }

    private static void placeSpeech(ObjectNode config, String host) {
        for (JsonNode m : config.path("methods")) {
            if (m.path("id").asText().equals("speech")) {
                ((ObjectNode) m).put("host", host);
                return;
            }
        }
        throw new AssertionError("config/aibo.json has no method 'speech'");
    }

    static JsonNode status(SimulatedDeployment rig) throws Exception {
        int port = JSON.readTree(Files.readString(rig.config)).path("status").path("port").asInt();
        try (Socket s = new Socket("127.0.0.1", port)) {
            s.setSoTimeout(5_000);
            return JSON.readTree(new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8))
                    .readLine());
        }
    }

    static JsonNode method(JsonNode status, String id) {
        for (JsonNode m : status.path("methods")) {
            if (m.path("id").asText().equals(id)) {
                return m;
            }
        }
        throw new AssertionError("no method " + id + " in " + status);
    }
}
