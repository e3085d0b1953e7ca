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
 * daemon with a wrong proof is refused and places nothing.
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
        try (DaemonProcess worker = DaemonProcess.startWrapped(wrapper, dir.resolve("worker.log"), "worker",
                "--port", "" + workerPort, "--bind", address, "--secret-file", secretFile.toString());
             SimulatedDeployment rig = new SimulatedDeployment("aibo", "aibo-arena", 1, dir, c -> {
                 placeSpeech(c, host);
                 c.putObject("security").put("credentials", credentials.toAbsolutePath().toString());
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
        }
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
