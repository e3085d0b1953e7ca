package org.habla.graph;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.plugin.PluginRegistry;
import org.habla.recording.RecordedEvent;
import org.habla.recording.Recorder;
import org.habla.recording.RecordingHeader;
import org.habla.recording.RecordingReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A daemon whose config names a credentials file: its sockets and status endpoint require authentication, and
 * every command, accepted or refused, reaches the audit log beside the config and the recording.
 */
@Timeout(60)
class SecuredDaemonTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String TOKEN = "mdb-token-0123456789abcdef";

    @TempDir
    Path dir;

    @Test
    void everyCommandAcceptedOrRefusedIsInTheAuditLogAndTheRecording() throws Exception {
        PluginRegistry registry = TestMethods.registry();
        Files.writeString(Files.createFile(dir.resolve("lab.credentials.json"),
                PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------"))), """
                {"clients": [{"name": "mdb", "token": "%s", "roles": {"cmd": "command", "@status": "read"}}]}
                """.formatted(TOKEN));
        int[] ports = org.habla.testing.DaemonProcess.freePorts(2);
        Path configFile = dir.resolve("secured.json");
        Files.writeString(configFile, """
                {"system": "secured", "safety": {"watchdogMs": 0}, "status": {"port": %d},
                 "security": {"credentials": "lab.credentials.json", "loopback": "authenticated"},
                 "methods": [{"id": "cmd", "type": "command-virtual", "layer": "virtual", "inputs": {"in": "control"},
                              "expose": {"port": %d}}]}
                """.formatted(ports[0], ports[1]));
        HablaConfig cfg = new ConfigLoader(registry).load(configFile);
        EngineClock clock = EngineClock.system();
        Path recording = dir.resolve("run.habla-rec");
        try (Recorder recorder = Recorder.create(recording, new RecordingHeader(clock.nowMicros(), 1,
                (ObjectNode) JSON.readTree(Files.readString(configFile)), dir.toString(),
                MethodGraph.channels(cfg, registry)), clock);
                Daemon daemon = Daemon.start(cfg, registry, clock, recorder)) {
            assertThat(exchange(daemon.port("cmd"), "{\"value\": 1}"))
                    .last().asString().contains("auth_required");
            List<String> answers = exchange(daemon.port("cmd"),
                    "{\"op\":\"auth\",\"client\":\"mdb\",\"token\":\"" + TOKEN + "\"}", "{\"value\": 2, \"id\": 1}");
            assertThat(answers).anySatisfy(l -> assertThat(l).contains("\"type\":\"ok\""));
            assertThat(exchange(daemon.statusPort(),
                    "{\"op\":\"auth\",\"client\":\"mdb\",\"token\":\"" + TOKEN + "\"}"))
                    .last().asString().contains("\"system\":\"secured\"");
            assertThat(recorder.flush(10_000)).isTrue();
        }
        List<JsonNode> audit = Files.readAllLines(dir.resolve("habla-audit.log")).stream().map(SecuredDaemonTest::json)
                .toList();
        assertThat(audit).extracting(e -> e.path("client").asText() + " " + e.path("accepted").asBoolean())
                .containsExactly("anonymous false", "mdb true");
        List<RecordedEvent.Audit> recorded = RecordingReader.readAll(recording).events(RecordedEvent.Audit.class);
        assertThat(recorded).extracting(a -> a.entry().path("client").asText() + " " + a.entry().path("value"))
                .containsExactly("anonymous 1", "mdb 2");
    }

    /** Sends lines on a new connection; returns every line the daemon sends until it closes or falls silent. */
    private static List<String> exchange(int port, String... lines) throws Exception {
        try (Socket s = new Socket("127.0.0.1", port)) {
            s.setSoTimeout(3_000);
            for (String line : lines) {
                s.getOutputStream().write((line + "\n").getBytes(UTF_8));
            }
            s.getOutputStream().flush();
            BufferedReader in = new BufferedReader(new InputStreamReader(s.getInputStream(), UTF_8));
            List<String> got = new java.util.ArrayList<>();
            try {
                for (String l = in.readLine(); l != null && got.size() < 100; l = in.readLine()) {
                    got.add(l);
                    if (l.contains("\"type\":\"ok\"")) {
                        break;
                    }
                }
            } catch (java.net.SocketTimeoutException e) {
                // silent: the answers are in
            }
            return got;
        }
    }

    private static JsonNode json(String line) {
        try {
            return JSON.readTree(line);
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
    }
}
