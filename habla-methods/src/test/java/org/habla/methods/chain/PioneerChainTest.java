package org.habla.methods.chain;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import org.habla.config.ConfigLoader;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The Pioneer's chain of general methods in a real daemon, against a robot behind HABLA's interface
 * protocol on loopback: sonar → nearest-distance → distance-angle up to a control socket, and action →
 * movement-safety → motion-composition → wheels down to the robot's motion channel, with the top speed
 * taken from the channel's metadata.
 */
@Timeout(60)
class PioneerChainTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    private static final String CHANNELS = """
            [{"name": "sonar", "direction": "reading", "kind": "vector", "unit": "m",
              "meta": {"maxRangeM": 5.0, "poses": [{"xM": 0.2, "yM": 0, "thetaRad": 0},
                        {"xM": 0, "yM": 0.2, "thetaRad": 1.5708}, {"xM": -0.2, "yM": 0, "thetaRad": 3.1416}]}},
             {"name": "motion", "direction": "command", "kind": "vector", "unit": "m/s, rad/s", "motion": true,
              "meta": {"maxVelMps": 0.3, "maxRotVelRadps": 1.0}}]""";

    private static final String CONFIG = """
            {"system": "pioneer-chain-test", "safety": {"watchdogMs": 0}, "status": {"port": 0},
             "interfaces": [{"id": "robot", "driver": "habla", "address": "127.0.0.1:%d",
                             "params": {"channels": %s}}],
             "methods": [
              {"id": "sonar", "type": "sonar", "layer": "sensors_actuators", "inputs": {"ranges": "@robot.sonar"}},
              {"id": "nearest", "type": "nearest-distance", "layer": "processing", "inputs": {"scan": "sonar.scan"}},
              {"id": "distance", "type": "distance-angle", "layer": "virtual", "inputs": {"nearest": "nearest.nearest"},
               "expose": {"port": %d, "name": "distance_angle"}},
              {"id": "action", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
               "params": {"forwardMps": 0.5, "durationMs": 30000}, "expose": {"port": %d, "name": "action"}},
              {"id": "safety", "type": "movement-safety", "layer": "processing",
               "inputs": {"motion": "action.motion", "nearest": "nearest.nearest", "limits": "wheels.limits"},
               "feedback": ["limits"]},
              {"id": "compose", "type": "motion-composition", "layer": "processing",
               "inputs": {"motion": "safety.motion", "limits": "wheels.limits"}, "feedback": ["limits"]},
              {"id": "wheels", "type": "wheels", "layer": "sensors_actuators",
               "inputs": {"motion": "compose.motion"}, "commands": {"motion": "@robot.motion"}}]}
            """;

    @Test
    void forwardRampsUpToTheChannelsTopSpeedAndAWallAheadStopsIt() throws Exception {
        String hello = "{\"type\":\"hello\",\"protocol\":\"habla-interface/1\",\"robot\":\"rover\",\"channels\":"
                + CHANNELS + "}";
        try (InterfaceRobot robot = new InterfaceRobot(hello.replaceAll("\\s+", " "), 3.0, 2.0, 4.0)) {
            int[] sockets = org.habla.testing.DaemonProcess.freePorts(2); // held together, so never the same port twice
            String json = CONFIG.formatted(robot.port(), CHANNELS, sockets[0], sockets[1]);
            PluginRegistry registry = PluginRegistry.discover();
            try (Daemon daemon = Daemon.start(new ConfigLoader(registry).parse(json), registry, EngineClock.system());
                    Socket action = new Socket("127.0.0.1", daemon.port("action"));
                    Socket distance = new Socket("127.0.0.1", daemon.port("distance_angle"))) {
                action.setSoTimeout(5_000);
                distance.setSoTimeout(5_000);
                BufferedReader seen = new BufferedReader(new InputStreamReader(distance.getInputStream(), UTF_8));
                JsonNode first = nextSample(seen);
                assertThat(first.path("value").path("distanceM").asDouble()).isCloseTo(2.0, within(1e-9));
                assertThat(first.path("value").path("angleRad").asDouble()).isCloseTo(Math.PI / 2, within(1e-3));

                action.getOutputStream().write("{\"value\": \"forward\"}\n".getBytes(UTF_8));
                List<Double> speeds = new ArrayList<>();
                for (int i = 0; i < 200 && (speeds.isEmpty() || speeds.get(speeds.size() - 1) < 0.3 - 1e-9); i++) {
                    JsonNode cmd = robot.next("command", 5_000);
                    assertThat(cmd).as("a motion command reaches the robot").isNotNull();
                    speeds.add(cmd.path("value").get(0).asDouble());
                }
                assertThat(speeds.get(speeds.size() - 1)).as("the channel's top speed, not the asked 0.5")
                        .isCloseTo(0.3, within(1e-9));
                // 12 steps of 0.025 m/s normally; a busy machine may conflate a few (the newest motion wins)
                assertThat(speeds).as("ramped, not jumped: " + speeds).hasSizeGreaterThanOrEqualTo(4).isSorted();
                assertThat(speeds.get(0)).as("the ramp starts low").isLessThan(0.1);

                robot.ranges(0.2, 2.0, 4.0);
                double last = 0.3;
                for (int i = 0; i < 200 && last > 0; i++) {
                    JsonNode cmd = robot.next("command", 5_000);
                    assertThat(cmd).as("the robot is told to slow down").isNotNull();
                    last = cmd.path("value").get(0).asDouble();
                }
                assertThat(last).as("stopped before the wall").isEqualTo(0.0);
            }
        }
    }

    @Test
    void theLinkSocketTellsWhenTheRobotGoesAway() throws Exception {
        String hello = "{\"type\":\"hello\",\"protocol\":\"habla-interface/1\",\"robot\":\"rover\",\"channels\":"
                + CHANNELS + "}";
        InterfaceRobot robot = new InterfaceRobot(hello.replaceAll("\\s+", " "), 3.0, 2.0, 4.0);
        String json = """
                {"system": "link-test", "safety": {"watchdogMs": 0}, "status": {"port": 0},
                 "interfaces": [{"id": "robot", "driver": "habla", "address": "127.0.0.1:%d",
                                 "reconnect": {"initialMs": 100, "maxMs": 200},
                                 "params": {"channels": %s}}],
                 "methods": [
                  {"id": "link-raw", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@robot.link"},
                   "params": {"kind": "record"}},
                  {"id": "link-up", "type": "pass-through", "layer": "processing", "inputs": {"in": "link-raw.out"}},
                  {"id": "link", "type": "link-state", "layer": "virtual", "inputs": {"link": "link-up.out"},
                   "expose": {"port": %d, "name": "link"}}]}
                """.formatted(robot.port(), CHANNELS, freePort());
        PluginRegistry registry = PluginRegistry.discover();
        try (robot; Daemon daemon = Daemon.start(new ConfigLoader(registry).parse(json), registry, EngineClock.system());
                Socket link = new Socket("127.0.0.1", daemon.port("link"))) {
            link.setSoTimeout(5_000);
            BufferedReader in = new BufferedReader(new InputStreamReader(link.getInputStream(), UTF_8));
            JsonNode up = nextLink(in, true);
            assertThat(up.path("interface").asText()).isEqualTo("robot");
            assertThat(up.path("stale").asBoolean()).as("the first record saying connected is fresh").isFalse();
            robot.close();
            JsonNode down = nextLink(in, false);
            assertThat(down.path("stale").asBoolean()).as("the first record saying not connected is stale").isTrue();
            assertThat(down.path("sinceMs").asLong()).isLessThan(5_000);
            assertThat(down.path("detail").asText()).isNotEmpty();
        }
    }

    /** The next link record with {@code connected} as given (at most 100 lines, each within 5 s). */
    private static JsonNode nextLink(BufferedReader in, boolean connected) throws Exception {
        for (int i = 0; i < 100; i++) {
            JsonNode n = JSON.readTree(in.readLine());
            if (n.path("type").asText().equals("sample") && n.path("value").path("connected").asBoolean() == connected
                    && n.path("value").has("connected")) {
                return n.path("value");
            }
        }
        throw new AssertionError("no link record with connected " + connected + " in 100 lines");
    }

    private static JsonNode nextSample(BufferedReader in) throws Exception {
        for (int i = 0; i < 100; i++) {
            JsonNode n = JSON.readTree(in.readLine());
            if (n.path("type").asText().equals("sample") && n.path("value").path("seen").asBoolean()) {
                return n;
            }
        }
        throw new AssertionError("no sample with the target seen in 100 lines");
    }

    private static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }
}
