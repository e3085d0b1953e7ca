package org.habla.methods.chain;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.function.Predicate;
import org.habla.config.ConfigLoader;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The action socket of the Pioneer's chain (action → movement-safety → motion-composition → wheels) in a real
 * daemon, against a robot behind HABLA's interface protocol: what a control client is told and what the robot
 * is sent never disagree.
 */
@Timeout(60)
class ActionObedienceTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    private static final String CHANNELS = """
            [{"name": "sonar", "direction": "reading", "kind": "vector", "unit": "m",
              "meta": {"maxRangeM": 5.0, "poses": [{"xM": 0.2, "yM": 0, "thetaRad": 0},
                        {"xM": 0, "yM": 0.2, "thetaRad": 1.5708}, {"xM": -0.2, "yM": 0, "thetaRad": 3.1416}]}},
             {"name": "motion", "direction": "command", "kind": "vector", "unit": "m/s, rad/s", "motion": true,
              "meta": {"maxVelMps": 0.3, "maxRotVelRadps": 1.0}}]""";

    private static final String CONFIG = """
            {"system": "action-obedience-test", "safety": {"watchdogMs": 0}, "status": {"port": 0},
             "interfaces": [{"id": "robot", "driver": "habla", "address": "127.0.0.1:%d",
                             "params": {"channels": %s}}],
             "methods": [
              {"id": "sonar", "type": "sonar", "layer": "sensors_actuators", "inputs": {"ranges": "@robot.sonar"}},
              {"id": "nearest", "type": "nearest-distance", "layer": "processing", "inputs": {"scan": "sonar.scan"}},
              {"id": "action", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
               "params": {"forwardMps": 0.25, "durationMs": 30000}, "expose": {"port": %d, "name": "action"}},
              {"id": "safety", "type": "movement-safety", "layer": "processing",
               "inputs": {"motion": "action.motion", "nearest": "nearest.nearest"},
               "params": {"stopDistanceM": 0.25}},
              {"id": "compose", "type": "motion-composition", "layer": "processing",
               "inputs": {"motion": "safety.motion"}},
              {"id": "wheels", "type": "wheels", "layer": "sensors_actuators",
               "inputs": {"motion": "compose.motion"}, "commands": {"motion": "@robot.motion"}}]}
            """;

    private InterfaceRobot robot;
    private Daemon daemon;

    @BeforeEach
    void start() throws Exception {
        String hello = "{\"type\":\"hello\",\"protocol\":\"habla-interface/1\",\"robot\":\"rover\",\"channels\":"
                + CHANNELS + "}";
        robot = new InterfaceRobot(hello.replaceAll("\\s+", " "), 3.0, 2.0, 4.0);
        PluginRegistry registry = PluginRegistry.discover();
        daemon = Daemon.start(new ConfigLoader(registry).parse(CONFIG.formatted(robot.port(), CHANNELS, freePort())),
                registry, EngineClock.system());
    }

    @AfterEach
    void stop() throws IOException {
        if (daemon != null) {
            daemon.close();
        }
        robot.close();
    }

    @Test
    void afterTheWatchdogStoppedTheRobotTheSameLabelAgainMovesItAndTheSocketSaysSo() throws Exception {
        try (Client first = new Client(daemon.port("action"))) {
            first.send("{\"value\":\"forward\",\"id\":1}");
            first.next(n -> n.path("type").asText().equals("ok"));
            awaitCommand(v -> Math.abs(v - 0.25) < 1e-9, "the ramp reaches the forward speed");
        }
        // The client that drove the robot left: the watchdog stops it.
        assertThat(robot.next("stop", 5_000)).as("the watchdog's stop").isNotNull();
        try (Client second = new Client(daemon.port("action"))) {
            JsonNode motion = second.latest("motion", 5_000, m -> m.get(0).asDouble() == 0);
            assertThat(motion).as("the action socket says the robot stands").isNotNull();
            second.send("{\"value\":\"forward\",\"id\":2}");
            second.next(n -> n.path("type").asText().equals("ok"));
            double v = awaitCommand(x -> x > 0, "the same label moves the robot again");
            assertThat(v).as("ramped up again from rest").isLessThan(0.25);
            awaitCommand(x -> Math.abs(x - 0.25) < 1e-9, "back at the forward speed");
        }
    }

    @Test
    void aSecondClientIsRefusedUntilItTakesControlAndTheStatusNamesTheCommander() throws Exception {
        try (Client first = new Client(daemon.port("action")); Client second = new Client(daemon.port("action"))) {
            first.send("{\"value\":\"forward\",\"id\":1}");
            first.next(n -> n.path("type").asText().equals("ok"));
            JsonNode control = socketStatus("action").path("control");
            assertThat(control.path("holder").path("connection").asText()).isEqualTo("action#1");
            second.send("{\"value\":\"back\",\"id\":2}");
            JsonNode busy = second.next(n -> n.path("type").asText().equals("error"));
            assertThat(busy.path("code").asText()).isEqualTo("busy");
            assertThat(busy.path("message").asText()).contains("action#1", "since");
            second.send("{\"op\":\"take\",\"id\":3}");
            second.next(n -> n.path("type").asText().equals("ok"));
            JsonNode told = first.next(n -> n.path("type").asText().equals("control")
                    && n.path("holder").path("connection").asText().equals("action#2"));
            assertThat(told.path("why").asText()).contains("taken from action#1");
            second.send("{\"value\":\"back\",\"id\":4}");
            second.next(n -> n.path("type").asText().equals("ok"));
            awaitCommand(v -> v < 0, "the new commander backs the robot");
            assertThat(socketStatus("action").path("control").path("holder").path("connection").asText())
                    .isEqualTo("action#2");
        }
    }

    @Test
    void aMoveVetoedByMovementSafetyIsToldToTheClientWithTheReasonAndTheLimit() throws Exception {
        robot.ranges(0.1, 2.0, 4.0); // a wall right ahead
        try (Client client = new Client(daemon.port("action"))) {
            // Until the new ranges are in, a write may still be let through; the veto then begins on the held
            // motion, told with the time of the range reading. Write until a write of its own is vetoed.
            JsonNode veto = null;
            for (int id = 1; id < 100 && veto == null; id++) {
                JsonNode[] told = writeForward(client, id);
                if (told[1].path("t").asLong() == told[0].path("t").asLong()
                        && told[1].path("detail").path("reason").asText().equals("obstacle_ahead")) {
                    veto = told[1];
                }
            }
            assertThat(veto).as("a veto of the write, naming the obstacle").isNotNull();
            assertThat(veto.path("notice").asText()).isEqualTo("veto");
            assertThat(veto.path("method").asText()).isEqualTo("safety");
            assertThat(veto.path("message").asText()).contains("forward motion vetoed", "stop distance 0.25 m");
            assertThat(veto.path("detail").path("stopDistanceM").asDouble()).isEqualTo(0.25);
            assertThat(veto.path("detail").path("obstacleM").asDouble()).isLessThan(0.25);
            for (int i = 0; i < 1_000 && robot.next("command", 300) != null; i++) {
                // what an early write let through has braked to a stand
            }
            JsonNode[] again = writeForward(client, 1_000);
            assertThat(again[1].path("t").asLong()).as("the notice is the write's").isEqualTo(again[0].path("t").asLong());
            JsonNode cmd = robot.next("command", 300);
            assertThat(cmd == null || cmd.path("value").get(0).asDouble() == 0).as("nothing drives the robot: %s", cmd)
                    .isTrue();
        }
    }

    /** Writes forward; returns its echo and the next notice. */
    private static JsonNode[] writeForward(Client client, int id) throws IOException {
        client.send("{\"value\":\"forward\",\"id\":" + id + "}");
        JsonNode echo = client.next(n -> n.path("type").asText().equals("sample")
                && n.path("output").asText().equals("action"));
        JsonNode notice = client.next(n -> n.path("type").asText().equals("notice"));
        return new JsonNode[] {echo, notice};
    }

    private JsonNode socketStatus(String name) {
        for (JsonNode s : daemon.status().path("sockets")) {
            if (s.path("socket").asText().equals(name)) {
                return s;
            }
        }
        throw new AssertionError("no socket " + name + " in the status");
    }

    /** The forward speed of the next motion command that satisfies {@code wanted}, within 5 s. */
    private double awaitCommand(Predicate<Double> wanted, String what) throws InterruptedException {
        long end = System.nanoTime() + 5_000_000_000L;
        while (System.nanoTime() < end) {
            JsonNode cmd = robot.next("command", Math.max(1, (end - System.nanoTime()) / 1_000_000));
            if (cmd != null && wanted.test(cmd.path("value").get(0).asDouble())) {
                return cmd.path("value").get(0).asDouble();
            }
        }
        throw new AssertionError("no motion command within 5 s: " + what);
    }

    private static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    /** A control client of one socket: lines out, JSON lines in, every read bounded. */
    static final class Client implements AutoCloseable {
        private final Socket socket;
        private final BufferedReader in;

        Client(int port) throws IOException {
            socket = new Socket("127.0.0.1", port);
            socket.setSoTimeout(5_000);
            in = new BufferedReader(new InputStreamReader(socket.getInputStream(), UTF_8));
        }

        void send(String line) throws IOException {
            socket.getOutputStream().write((line + "\n").getBytes(UTF_8));
            socket.getOutputStream().flush();
        }

        /** The next line that matches, among at most 1 000 (each within 5 s). */
        JsonNode next(Predicate<JsonNode> wanted) throws IOException {
            for (int i = 0; i < 1_000; i++) {
                String line = in.readLine();
                if (line == null) {
                    throw new AssertionError("the socket closed");
                }
                JsonNode n = JSON.readTree(line);
                if (wanted.test(n)) {
                    return n;
                }
            }
            throw new AssertionError("no matching line among 1 000");
        }

        /** Asks for the latest samples until {@code output}'s value satisfies {@code wanted}; null after the wait. */
        JsonNode latest(String output, long millis, Predicate<JsonNode> wanted) throws IOException, InterruptedException {
            long end = System.nanoTime() + millis * 1_000_000;
            int id = 1000;
            while (System.nanoTime() < end) {
                send("{\"op\":\"latest\",\"id\":" + ++id + "}");
                JsonNode found = null;
                for (JsonNode n = next(x -> true); !n.path("type").asText().equals("ok"); n = next(x -> true)) {
                    if (n.path("type").asText().equals("sample") && n.path("output").asText().equals(output)
                            && wanted.test(n.path("value"))) {
                        found = n.path("value");
                    }
                }
                if (found != null) {
                    return found;
                }
                Thread.sleep(20);
            }
            return null;
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }
}
