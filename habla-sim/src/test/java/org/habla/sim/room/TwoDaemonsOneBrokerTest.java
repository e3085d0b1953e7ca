package org.habla.sim.room;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.HashMap;
import java.util.Map;
import java.util.function.Predicate;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.sim.pioneer.PioneerSim;
import org.habla.sim.pioneer.PioneerSimOptions;
import org.habla.sim.world.World;
import org.habla.testing.DaemonProcess;
import org.habla.testing.Mosquitto;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Pioneer's daemon and the room's daemon on one broker, each with a bridge that publishes a socket and an
 * {@code mqtt} interface that reads the other's: the room's occupancy reaches the robot's control program, the
 * robot's pose reaches the room's, and either daemon can restart while the other only sees its data go stale and
 * come back, its own broker link never dropping.
 */
@Timeout(120)
class TwoDaemonsOneBrokerTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final PluginRegistry REGISTRY = PluginRegistry.discover();
    private static final Path CONFIGS = Paths.get("..", "config").toAbsolutePath().normalize();

    @Test
    void occupancyReachesTheRobotPoseReachesTheRoomAndARestartIsOnlyStalenessForTheOther(@TempDir Path tmp)
            throws Exception {
        try (Mosquitto broker = Mosquitto.start(tmp);
                PioneerSim pioneer = PioneerSim.start(PioneerSimOptions.forTest(World.builtIn("pioneer-room"), 1));
                RoomSim room = RoomSim.start(new RoomSimOptions("127.0.0.1", broker.port(), "zigbee2mqtt", 1, 5, 600,
                        0.75, 0.5, 0))) {
            int[] ports = DaemonProcess.freePorts(16);
            HablaConfig robotConfig = robotConfig(broker, pioneer, ports);
            HablaConfig roomConfig = roomConfig(broker, ports);
            int roomOccupancyAtRobot = port(robotConfig, "room_occupancy");
            int robotPoseAtRoom = port(roomConfig, "robot_pose");
            Daemon robotDaemon = Daemon.start(robotConfig, REGISTRY, EngineClock.system());
            Daemon roomDaemon = Daemon.start(roomConfig, REGISTRY, EngineClock.system());
            try (Lines robotProgram = new Lines(roomOccupancyAtRobot); Lines roomProgram = new Lines(robotPoseAtRoom)) {
                JsonNode occupancy = robotProgram.freshSample();
                assertThat(occupancy.path("value").path("zones").has("desk")).as(occupancy.toString()).isTrue();
                JsonNode pose = roomProgram.freshSample();
                assertThat(pose.path("value").isObject()).as(pose.toString()).isTrue();

                // The room's daemon restarts: the robot's program sees the occupancy go stale, then fresh again.
                roomDaemon.close();
                assertThat(robotProgram.staleness(true).path("why").asText()).contains("room-daemon is offline");
                roomDaemon = Daemon.start(roomConfig, REGISTRY, EngineClock.system());
                robotProgram.staleness(false);
                assertThat(robotProgram.freshSample().path("value").path("zones").has("desk")).isTrue();
                assertThat(houseLink(robotDaemon).path("connects").asLong()).as("the robot's broker link never dropped")
                        .isEqualTo(1);

                // The robot's daemon restarts: the room's program sees the pose go stale, then fresh again.
                try (Lines roomProgramAgain = new Lines(robotPoseAtRoom)) {
                    roomProgramAgain.freshSample();
                    robotDaemon.close();
                    assertThat(roomProgramAgain.staleness(true).path("why").asText()).contains("pioneer-daemon is offline");
                    robotDaemon = Daemon.start(robotConfig, REGISTRY, EngineClock.system());
                    roomProgramAgain.staleness(false);
                    assertThat(roomProgramAgain.freshSample().path("value").isObject()).isTrue();
                    assertThat(houseLink(roomDaemon).path("connects").asLong()).isEqualTo(1);
                }
            } finally {
                robotDaemon.close();
                roomDaemon.close();
            }
        }
    }

    /** config/pioneer.json against the simulated robot, reading the room's occupancy and publishing its pose. */
    private static HablaConfig robotConfig(Mosquitto broker, PioneerSim sim, int[] ports) throws Exception {
        ObjectNode root = load("pioneer.json");
        Map<String, Integer> simPorts = Map.of("robot", sim.arcosPort(), "mic", sim.micPort(), "keys", sim.keysPort());
        for (JsonNode i : root.get("interfaces")) {
            ((ObjectNode) i).put("address", "127.0.0.1:" + simPorts.get(i.get("id").asText()));
        }
        addPeer(root, broker, "room-daemon", "habla/room/availability", "room_occupancy", "habla/room/occupancy");
        bridge(root, broker, "pose");
        return parse(root, ports, 0);
    }

    /** config/room.json on the test's broker, reading the robot's pose and publishing the occupancy. */
    private static HablaConfig roomConfig(Mosquitto broker, int[] ports) throws Exception {
        ObjectNode root = load("room.json");
        ((ObjectNode) root.get("interfaces").get(0)).put("address", broker.address());
        addPeer(root, broker, "pioneer-daemon", "habla/pioneer-2dx/availability", "robot_pose", "habla/pioneer-2dx/pose");
        bridge(root, broker, "occupancy");
        return parse(root, ports, 8);
    }

    /**
     * An {@code mqtt} interface "house" that reads another daemon's bridged socket (its sample line's value) as a
     * record channel, stale while that daemon is offline, and three methods that expose it as {@code socket}.
     */
    private static void addPeer(ObjectNode root, Mosquitto broker, String device, String availability, String socket,
            String topic) {
        ObjectNode house = ((ArrayNode) root.get("interfaces")).addObject().put("id", "house").put("driver", "mqtt")
                .put("address", broker.address());
        house.putObject("reconnect").put("initialMs", 100).put("maxMs", 500);
        ObjectNode params = house.putObject("params");
        params.putArray("devices").addObject().put("name", device).put("availabilityTopic", availability);
        params.putArray("readings").addObject().put("channel", "peer").put("topic", topic).put("field", "value")
                .put("kind", "record").put("device", device);
        ArrayNode methods = (ArrayNode) root.get("methods");
        relay(methods, "peer-raw", "channel", "sensors_actuators", "@house.peer");
        relay(methods, "peer-up", "pass-through", "processing", "peer-raw.out");
        relay(methods, socket, "pass-through", "virtual", "peer-up.out").putObject("expose").put("port", 1)
                .put("name", socket);
    }

    private static ObjectNode relay(ArrayNode methods, String id, String type, String layer, String source) {
        ObjectNode m = methods.addObject().put("id", id).put("type", type).put("layer", layer);
        m.putObject("inputs").put("in", source);
        m.putObject("params").put("kind", "record");
        return m;
    }

    private static void bridge(ObjectNode root, Mosquitto broker, String socket) {
        ObjectNode b = root.putArray("bridges").addObject().put("id", "house").put("type", "mqtt")
                .put("address", broker.address());
        b.putObject("params").put("discovery", false).putArray("publish").add(socket);
    }

    private static ObjectNode load(String name) throws IOException {
        ObjectNode root = (ObjectNode) JSON.readTree(CONFIGS.resolve(name).toFile());
        root.remove("$schema");
        ((ObjectNode) root.get("status")).put("port", 0).put("monitorPort", 0); // a daemon on this machine may hold 7098
        return root;
    }

    /** Parses a config with its control ports moved to free ones, from {@code ports[first]} on. */
    private static HablaConfig parse(ObjectNode root, int[] ports, int first) throws Exception {
        int next = first;
        for (JsonNode m : root.get("methods")) {
            if (m.has("expose")) {
                ((ObjectNode) m.get("expose")).put("port", ports[next++]);
            }
        }
        return new ConfigLoader(REGISTRY).parse(root.toString(), CONFIGS);
    }

    private static int port(HablaConfig config, String socket) {
        return config.methods().stream().flatMap(m -> m.expose().stream()).filter(x -> x.name().equals(socket))
                .findFirst().orElseThrow().port();
    }

    private static JsonNode houseLink(Daemon daemon) {
        for (JsonNode i : daemon.status().path("interfaces")) {
            if (i.path("id").asText().equals("house")) {
                return i.path("connections").get(0);
            }
        }
        throw new AssertionError("no interface 'house'");
    }

    /** A control program's socket: JSON lines, every read bounded. */
    private static final class Lines implements AutoCloseable {
        private final Socket socket;
        private final BufferedReader in;

        Lines(int port) throws IOException {
            socket = new Socket("127.0.0.1", port);
            socket.setSoTimeout(15_000);
            in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
        }

        JsonNode next(Predicate<JsonNode> wanted, String what) throws IOException {
            for (int i = 0; i < 10_000; i++) {
                String line;
                try {
                    line = in.readLine();
                } catch (SocketTimeoutException e) {
                    throw new AssertionError("no " + what + " within 15 s", e);
                }
                assertThat(line).as("the socket closed before " + what).isNotNull();
                JsonNode n = JSON.readTree(line);
                if (wanted.test(n)) {
                    return n;
                }
            }
            throw new AssertionError("no " + what + " in 10 000 lines");
        }

        JsonNode freshSample() throws IOException {
            return next(n -> n.path("type").asText().equals("sample") && !n.path("stale").asBoolean(), "a fresh sample");
        }

        JsonNode staleness(boolean stale) throws IOException {
            return next(n -> n.path("type").asText().equals("stale") && n.path("stale").asBoolean() == stale,
                    "stale=" + stale);
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }
}
