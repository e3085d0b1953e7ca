package org.habla.sim.room;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.habla.config.ConfigLoader;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.habla.testing.Mosquitto;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The simulated room and config/room.json end to end: a real Mosquitto broker, the simulator's devices on it as
 * Zigbee2MQTT's, the daemon with the room's config (its broker and ports moved), and a control program in Python
 * that knows only the sockets.
 */
@Timeout(90)
class RoomEndToEndTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Path CONFIG = Paths.get("..", "config", "room.json").toAbsolutePath().normalize();
    private static final Path CLIENT = Paths.get("src/test/resources/e2e/room_client.py").toAbsolutePath();
    private static final Path CLIENT_LIB = Paths.get("..", "clients", "python", "src").toAbsolutePath().normalize();

    /** config/room.json on another broker and other ports: occupancy, light, comfort, reward, action. */
    static String roomConfig(int brokerPort, int[] ports) throws Exception {
        ObjectNode root = (ObjectNode) JSON.readTree(CONFIG.toFile());
        root.remove("$schema");
        ((ObjectNode) root.get("interfaces").get(0)).put("address", "127.0.0.1:" + brokerPort);
        ((ObjectNode) root.get("status")).put("port", 0).put("monitorPort", 0); // a daemon on this machine may hold 7098
        List<String> names = List.of("occupancy", "light", "comfort", "reward", "action");
        for (JsonNode m : root.get("methods")) {
            if (m.has("expose")) {
                ((ObjectNode) m.get("expose")).put("port", ports[names.indexOf(m.get("expose").get("name").asText())]);
            }
        }
        return root.toString();
    }

    @Test
    void aPythonProgramSeesWhoIsWhereAndLightsTheDeskThroughTheBrokerAndTheSimulatedLamp(@TempDir Path tmp)
            throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        int[] ports = DaemonProcess.freePorts(5);
        // Midnight: the only light is the lamps'. The person starts at the desk and stays there 15 s or more.
        try (Mosquitto broker = Mosquitto.start(tmp);
                RoomSim sim = RoomSim.start(new RoomSimOptions("127.0.0.1", broker.port(), "zigbee2mqtt", 1, 3, 600,
                        0.75, 0.5, 0));
                Daemon daemon = Daemon.start(new ConfigLoader(registry).parse(roomConfig(broker.port(), ports)),
                        registry, EngineClock.system())) {
            List<JsonNode> findings = runClient(ports[0], ports[1], ports[4]);

            assertThat(findings.get(0).path("occupied").toString()).isEqualTo("[\"desk\"]");
            assertThat(findings.get(0).path("stale").asBoolean()).isFalse();
            double off = findings.get(1).path("off").asDouble();
            assertThat(off).isLessThan(100);
            assertThat(findings.get(2).path("lit").asDouble()).as("the desk lamp lit the desk")
                    .isGreaterThanOrEqualTo(off + RoomModel.LAMP_LUX - 1);
            assertThat(findings.get(3).path("off_again").isNull()).as("the desk went dark again").isFalse();
            assertThat(findings.get(4).path("refused").asText()).isEqualTo("bad_value");
            assertThat(findings.get(4).path("message").asText()).contains("desk", "sofa", "kitchen");
            assertThat(daemon.status().path("interfaces").get(0).path("malformed").asLong()).isZero();
        }
    }

    private static List<JsonNode> runClient(int occupancy, int light, int action) throws Exception {
        ProcessBuilder pb = new ProcessBuilder("python3", CLIENT.toString(), "--occupancy", String.valueOf(occupancy),
                "--light", String.valueOf(light), "--action", String.valueOf(action));
        pb.environment().put("PYTHONPATH", CLIENT_LIB.toString());
        pb.redirectErrorStream(true);
        Process p = pb.start();
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).as("the Python client finished").isTrue();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.exitValue()).as(out).isZero();
        List<JsonNode> findings = new ArrayList<>();
        for (String line : out.split("\n")) {
            if (line.startsWith("{")) {
                findings.add(JSON.readTree(line));
            }
        }
        assertThat(findings).as(out).hasSize(5);
        return findings;
    }
}
