package org.habla.e2e;

import static org.assertj.core.api.Assertions.assertThat;

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
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.habla.testing.DaemonProcess;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The whole path over real loopback sockets, with each part where a user would have it: the daemon in a
 * process of its own, a control client in Python, and a robot-side interface program speaking the HABLA
 * interface protocol.
 */
@Timeout(120)
class InterfaceProtocolEndToEndTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Path CLIENT = Paths.get("src/test/resources/e2e/control_client.py").toAbsolutePath();
    private static final Path CLIENT_LIB = Paths.get("..", "clients", "python", "src").toAbsolutePath().normalize();

    /** ir → channel → pass-through → pass-through (exposed "ranges"); control "wheels" → ... → @rover.wheels. */
    static ObjectNode config(int robotPort, int rangesPort, int wheelsPort, int statusPort, long watchdogMs) {
        ObjectNode c = JSON.createObjectNode().put("system", "e2e-rover");
        c.putObject("safety").put("watchdogMs", watchdogMs);
        c.putObject("status").put("port", statusPort);
        ObjectNode iface = c.putArray("interfaces").addObject().put("id", "rover").put("driver", "habla")
                .put("address", "127.0.0.1:" + robotPort);
        ObjectNode params = iface.putObject("params").put("keepAliveMs", 200);
        params.set("channels", TestInterfaceServer.channels());
        iface.putObject("reconnect").put("initialMs", 100).put("maxMs", 400);
        ArrayNode m = c.putArray("methods");
        method(m, "ir", "channel", "sensors_actuators", "@rover.ir", "vector");
        method(m, "ir-relay", "pass-through", "processing", "ir.out", "vector");
        method(m, "ranges", "pass-through", "virtual", "ir-relay.out", "vector")
                .putObject("expose").put("port", rangesPort).put("name", "ranges");
        method(m, "drive", "pass-through", "virtual", "control", "vector")
                .putObject("expose").put("port", wheelsPort).put("name", "wheels");
        method(m, "drive-relay", "pass-through", "processing", "drive.out", "vector");
        method(m, "wheels", "pass-through", "sensors_actuators", "drive-relay.out", "vector")
                .putObject("commands").put("out", "@rover.wheels");
        return c;
    }

    private static ObjectNode method(ArrayNode methods, String id, String type, String layer, String source,
            String kind) {
        ObjectNode o = methods.addObject().put("id", id).put("type", type).put("layer", layer);
        o.putObject("inputs").put("in", source);
        o.putObject("params").put("kind", kind);
        return o;
    }

    @Test
    void aPythonClientReadsSensesDrivesAndIsStoppedByTheWatchdogAndTheDaemonSurvivesTheRobotRestarting(
            @TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(4);
        try (TestInterfaceServer robot = new TestInterfaceServer(ports[0])) {
            Path cfg = tmp.resolve("rover.json");
            Files.writeString(cfg, config(ports[0], ports[1], ports[2], ports[3], 500).toPrettyString());
            try (DaemonProcess daemon = DaemonProcess.start(tmp.resolve("daemon.log"), "run", cfg.toString())) {
                assertThat(DaemonProcess.awaitPort(ports[1], DaemonProcess.START_MS)).as(daemon.output()).isTrue();
                assertThat(robot.awaitClient(10_000)).as(daemon.output()).isTrue();

                List<JsonNode> lines = runClient(ports[1], ports[2]);
                JsonNode hello = lines.get(0);
                assertThat(hello.path("event").asText()).isEqualTo("hello");
                assertThat(hello.path("protocol").asText()).isEqualTo("habla-control/1");
                assertThat(hello.path("method").asText()).isEqualTo("ranges");
                assertThat(hello.path("layer").asText()).isEqualTo("virtual");
                assertThat(hello.path("direction").asText()).isEqualTo("out");
                List<JsonNode> samples = lines.stream().filter(l -> l.path("event").asText().equals("sample")).toList();
                assertThat(samples).hasSize(3);
                for (JsonNode s : samples) {
                    assertThat(s.path("kind").asText()).isEqualTo("vector");
                    assertThat(s.path("value")).hasSize(2);
                    assertThat(s.path("value").get(1).asDouble()).isEqualTo(s.path("value").get(0).asDouble() * 0.5);
                }
                assertThat(samples.get(2).path("seq").asLong()).isGreaterThan(samples.get(0).path("seq").asLong());
                JsonNode wheelsHello = lines.stream().filter(l -> l.path("event").asText().equals("wheels-hello"))
                        .findFirst().orElseThrow();
                assertThat(wheelsHello.path("direction").asText()).isEqualTo("both");

                // The action reached the robot as a command, then the watchdog stopped it while the client
                // stayed connected but silent.
                JsonNode command = robot.next("command", 15_000);
                assertThat(command).isNotNull();
                assertThat(command.path("channel").asText()).isEqualTo("wheels");
                assertThat(command.path("value").get(0).asDouble()).isEqualTo(0.3);
                JsonNode stop = robot.next("stop", 15_000);
                assertThat(stop).as("the watchdog's stop").isNotNull();
                JsonNode watchdog = status(ports[3]).path("watchdog");
                assertThat(watchdog.path("trips").asLong()).as("one stop: %s", watchdog).isEqualTo(1);
                assertThat(watchdog.path("lastReason").asText()).as("stopped for the client's silence, not its leaving")
                        .startsWith("no control value for 500 ms");

                // The robot's interface server dies and comes back: stale, then fresh data.
                try (Socket watcher = new Socket("127.0.0.1", ports[1])) {
                    watcher.setSoTimeout(10_000);
                    BufferedReader in = new BufferedReader(
                            new InputStreamReader(watcher.getInputStream(), StandardCharsets.UTF_8));
                    assertThat(JSON.readTree(in.readLine()).path("type").asText()).isEqualTo("hello");
                    robot.close();
                    assertThat(nextOfType(in, "stale").path("stale").asBoolean()).isTrue();
                    try (TestInterfaceServer again = new TestInterfaceServer(ports[0])) {
                        assertThat(again.awaitClient(10_000)).isTrue();
                        assertThat(nextOfType(in, "stale").path("stale").asBoolean()).isFalse();
                        JsonNode fresh = nextOfType(in, "sample");
                        assertThat(fresh.path("stale").asBoolean()).isFalse();
                        assertThat(fresh.path("value").get(0).asDouble()).isGreaterThan(0);

                        // SIGTERM: the actuators are stopped first, then the link says goodbye; exit 0.
                        assertThat(daemon.terminate(15_000)).as(daemon.output()).isZero();
                        assertThat(again.next("stop", 15_000)).as(() -> String.format(
                                "stop on shutdown; the daemon said:%n%s", daemon.output())).isNotNull();
                        assertThat(again.next("bye", 15_000)).as(() -> String.format(
                                "bye on shutdown; the daemon said:%n%s", daemon.output())).isNotNull();
                    }
                }
            }
        }
    }

    /** The daemon's status snapshot. */
    private static JsonNode status(int port) throws IOException {
        try (Socket s = new Socket("127.0.0.1", port)) {
            s.setSoTimeout(15_000);
            return JSON.readTree(new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8))
                    .readLine());
        }
    }

    private static JsonNode nextOfType(BufferedReader in, String type) throws Exception {
        for (int i = 0; i < 1_000; i++) {
            String line = in.readLine();
            assertThat(line).as("the daemon closed the socket while waiting for " + type).isNotNull();
            JsonNode n = JSON.readTree(line);
            if (n.path("type").asText().equals(type)) {
                return n;
            }
        }
        throw new AssertionError("no " + type + " line in 1000 lines");
    }

    private static List<JsonNode> runClient(int rangesPort, int wheelsPort) throws Exception {
        ProcessBuilder pb = new ProcessBuilder("python3", CLIENT.toString(), "--ranges", String.valueOf(rangesPort),
                "--wheels", String.valueOf(wheelsPort), "--silence", "1.5");
        pb.environment().put("PYTHONPATH", CLIENT_LIB.toString());
        pb.redirectErrorStream(true);
        Process p = pb.start();
        List<JsonNode> lines = new ArrayList<>();
        StringBuilder raw = new StringBuilder();
        try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                raw.append(line).append('\n');
                if (line.startsWith("{")) {
                    lines.add(JSON.readTree(line));
                }
            }
        }
        assertThat(p.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as("python client output:\n" + raw).isZero();
        return lines;
    }
}
