package org.habla.sim.monitor;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.sim.aibo.AiboSimulator;
import org.habla.sim.aibo.TekkotsuPorts;
import org.habla.sim.world.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The monitor's Foxglove WebSocket server read by an independent client — the official {@code @foxglove/ws-protocol}
 * client in Node — against a daemon running the camera and distance chain of config/aibo.json on the simulated
 * Aibo: every method output is advertised with a JSON Schema, {@code distance_angle} arrives value for value and
 * at the rate of its control socket, the camera as {@code foxglove.CompressedImage} JPEG frames at the rate the
 * camera method emits them.
 */
@Timeout(180)
class FoxgloveClientTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Path NODE_DIR = Path.of("src/test/node");
    private static final Set<String> CHAIN = Set.of("camera", "head", "head-control", "segmentation", "translation",
            "distance");
    private static final int LISTEN_S = 6;

    @Test
    void anIndependentClientSeesDistanceAndCameraAsTheControlSocketAndTheEngineDo() throws Exception {
        assertThat(NODE_DIR.resolve("node_modules/@foxglove/ws-protocol")).as(
                "the Foxglove client is not installed: npm ci --prefix habla-sim/src/test/node (.ci/run does)").exists();
        try (AiboSimulator sim = new AiboSimulator(AiboSimulator.Options.defaults(World.builtIn("aibo-arena"))
                .onFreePorts().withTeacher(false))) {
            sim.start();
            PluginRegistry registry = PluginRegistry.discover(getClass().getClassLoader());
            HablaConfig cfg = new ConfigLoader(registry).parse(aiboChain(sim.ports()));
            try (Daemon daemon = Daemon.start(cfg, registry, EngineClock.system())) {
                awaitEmitted(daemon, "distance", "distance_angle", 5);
                awaitEmitted(daemon, "camera", "image", 5);

                Process probe = new ProcessBuilder("node", "foxglove-probe.mjs", "ws://127.0.0.1:" + daemon.extensionPort(Daemon.MONITOR),
                        Integer.toString(LISTEN_S), "/distance/distance_angle", "/camera/image")
                        .directory(NODE_DIR.toFile()).redirectError(ProcessBuilder.Redirect.INHERIT).start();
                long camerasBefore = emitted(daemon, "camera", "image");
                // The control socket listens from before the Foxglove client has started until it has ended, so that
                // its window holds the client's however slowly node starts on a busy machine.
                Map<Long, JsonNode> control = readControlSocket(daemon.port("distance_angle"), probe::isAlive, 60_000);
                long camerasDuring = emitted(daemon, "camera", "image") - camerasBefore;
                assertThat(probe.waitFor(60, TimeUnit.SECONDS)).as("the Foxglove client ended").isTrue();
                JsonNode out = JSON.readTree(new String(probe.getInputStream().readAllBytes(), StandardCharsets.UTF_8));
                assertThat(probe.exitValue()).as("client output: %s", out.path("error")).isZero();

                assertThat(out.at("/serverInfo/name").asText()).isEqualTo("HABLA aibo-ers7");
                assertThat(out.at("/serverInfo/capabilities").toString()).doesNotContain("clientPublish");
                assertThat(out.path("channels")).hasSize(daemon.graph().outputs().size());
                JsonNode distanceChannel = channel(out, "/distance/distance_angle");
                assertThat(distanceChannel.path("encoding").asText()).isEqualTo("json");
                assertThat(distanceChannel.path("schemaEncoding").asText()).isEqualTo("jsonschema");
                assertThat(distanceChannel.at("/schema/properties/value/properties").has("distanceM")).isTrue();
                assertThat(channel(out, "/camera/image").path("schemaName").asText()).isEqualTo("foxglove.CompressedImage");

                JsonNode distances = out.at("/topics/~1distance~1distance_angle");
                assertThat(distances.size()).as("distance_angle messages").isGreaterThanOrEqualTo(10);
                int compared = 0;
                for (JsonNode m : distances) {
                    JsonNode same = control.get(m.at("/msg/seq").asLong());
                    if (same != null) {
                        compared++;
                        assertThat(sameValue(m.at("/msg/value"), same.path("value")))
                                .as("sample #%s: %s vs %s", m.at("/msg/seq"), m.at("/msg/value"), same.path("value")).isTrue();
                        assertThat(m.at("/msg/sourceMicros").asLong()).isEqualTo(same.path("t").asLong());
                    }
                }
                assertThat(compared).as("samples seen on both").isGreaterThanOrEqualTo(distances.size() / 2);
                // The two clients listened for windows that started apart (node starts slower than a socket):
                // compare them where both listened, by the samples' running count.
                List<Long> foxgloveSeqs = new ArrayList<>();
                for (JsonNode m : distances) {
                    foxgloveSeqs.add(m.at("/msg/seq").asLong());
                }
                long lo = Math.max(foxgloveSeqs.stream().min(Long::compare).orElseThrow(),
                        control.keySet().stream().min(Long::compare).orElseThrow());
                long hi = Math.min(foxgloveSeqs.stream().max(Long::compare).orElseThrow(),
                        control.keySet().stream().max(Long::compare).orElseThrow());
                long fromLo = lo;
                long toHi = hi;
                long onFoxglove = foxgloveSeqs.stream().filter(q -> q >= fromLo && q <= toHi).count();
                long onSocket = control.keySet().stream().filter(q -> q >= fromLo && q <= toHi).count();
                assertThat(onSocket).as("samples %s..%s on the control socket", lo, hi).isPositive();
                assertThat((double) onFoxglove / onSocket).as("Foxglove %s vs control socket %s samples of #%s..#%s",
                        onFoxglove, onSocket, lo, hi).isBetween(0.75, 1.33);

                JsonNode frames = out.at("/topics/~1camera~1image");
                System.out.printf("foxglove: distance_angle %d messages (control socket %d), camera %d frames "
                        + "(camera emitted %d) in %d s%n", distances.size(), control.size(), frames.size(), camerasDuring,
                        LISTEN_S);
                assertThat(frames.size()).as("camera frames").isGreaterThanOrEqualTo(5);
                for (JsonNode f : frames) {
                    assertThat(f.at("/msg/format").asText()).isEqualTo("jpeg");
                    assertThat(f.at("/msg/dataHead/0").asInt()).isEqualTo(0xff);
                    assertThat(f.at("/msg/dataHead/1").asInt()).isEqualTo(0xd8);
                    assertThat(f.at("/msg/frame_id").asText()).isEqualTo("camera");
                }
                // How many of the camera's frames a client gets in a time depends on how busy the machine is; that
                // every one it gets is whole and in order is what holds.
                for (int i = 1; i < frames.size(); i++) {
                    assertThat(frames.get(i).at("/msg/timestamp/sec").asLong() * 1_000_000_000L
                            + frames.get(i).at("/msg/timestamp/nsec").asLong()).as("frame %s in order", i)
                            .isGreaterThan(frames.get(i - 1).at("/msg/timestamp/sec").asLong() * 1_000_000_000L
                                    + frames.get(i - 1).at("/msg/timestamp/nsec").asLong());
                }
            }
        }
    }

    /** Equal as values: numbers by their value (JavaScript writes 0.0 as 0), everything else exactly. */
    private static boolean sameValue(JsonNode a, JsonNode b) {
        if (a.isNumber() && b.isNumber()) {
            return a.doubleValue() == b.doubleValue();
        }
        if (a.isObject() && b.isObject()) {
            if (a.size() != b.size()) {
                return false;
            }
            for (var e : a.properties()) {
                if (!b.has(e.getKey()) || !sameValue(e.getValue(), b.get(e.getKey()))) {
                    return false;
                }
            }
            return true;
        }
        if (a.isArray() && b.isArray()) {
            if (a.size() != b.size()) {
                return false;
            }
            for (int i = 0; i < a.size(); i++) {
                if (!sameValue(a.get(i), b.get(i))) {
                    return false;
                }
            }
            return true;
        }
        return a.equals(b);
    }

    private static JsonNode channel(JsonNode out, String topic) {
        for (JsonNode c : out.path("channels")) {
            if (c.path("topic").asText().equals(topic)) {
                return c;
            }
        }
        throw new AssertionError("no channel " + topic + " advertised");
    }

    /** The samples a control client reads from a socket for a while, by sequence number. */
    /** The samples of the control socket at {@code port}, read while {@code reading} holds (at most {@code maxMillis}). */
    private static Map<Long, JsonNode> readControlSocket(int port, BooleanSupplier reading, long maxMillis) throws Exception {
        Map<Long, JsonNode> samples = new HashMap<>();
        try (Socket s = new Socket("127.0.0.1", port)) {
            s.setSoTimeout(200);
            BufferedReader in = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8));
            long end = System.currentTimeMillis() + maxMillis;
            while (reading.getAsBoolean() && System.currentTimeMillis() < end) {
                String line;
                try {
                    line = in.readLine();
                } catch (java.net.SocketTimeoutException e) {
                    continue;
                }
                if (line == null) {
                    break;
                }
                JsonNode m = JSON.readTree(line);
                if (m.path("type").asText().equals("sample")) {
                    samples.put(m.path("seq").asLong(), m);
                }
            }
        }
        return samples;
    }

    private static long emitted(Daemon daemon, String method, String output) {
        for (JsonNode m : daemon.status().path("methods")) {
            if (m.path("id").asText().equals(method)) {
                return m.path("outputs").path(output).asLong();
            }
        }
        return -1;
    }

    private static void awaitEmitted(Daemon daemon, String method, String output, long n) throws InterruptedException {
        long deadline = System.currentTimeMillis() + 60_000;
        while (emitted(daemon, method, output) < n) {
            assertThat(System.currentTimeMillis()).as("%s.%s never emitted %s samples", method, output, n)
                    .isLessThan(deadline);
            Thread.sleep(50);
        }
    }

    /** The camera and distance chain of config/aibo.json on the simulator's ports, with free ports of its own. */
    private static String aiboChain(TekkotsuPorts p) throws Exception {
        ObjectNode root = (ObjectNode) JSON.readTree(Files.readString(Path.of("../config/aibo.json")));
        ObjectNode params = (ObjectNode) root.withArray("interfaces").get(0).get("params");
        params.put("worldStatePort", p.worldState()).put("walkPort", p.walk()).put("headPort", p.head())
                .put("eStopPort", p.eStop()).put("microphonePort", p.microphone()).put("speakerPort", p.speaker())
                .put("cameraPort", p.rawCam()).put("controllerPort", p.controller());
        ArrayNode kept = JSON.createArrayNode();
        for (JsonNode m : root.withArray("methods")) {
            if (CHAIN.contains(m.path("id").asText())) {
                if (m.has("expose")) {
                    ((ObjectNode) m.get("expose")).put("port", MonitorInBrowserTest.freePort());
                }
                kept.add(m);
            }
        }
        root.set("methods", kept);
        root.putObject("status").put("port", 0).put("monitorPort", MonitorInBrowserTest.freePort());
        return JSON.writeValueAsString(root);
    }
}
