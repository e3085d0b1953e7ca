package org.habla.drivers.mqtt;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.habla.config.ConfigException;
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
 * The control side's MQTT bridge against a real Mosquitto broker, with {@code mosquitto_sub} and
 * {@code mosquitto_pub} as independent clients: samples as JSON on habla/SYSTEM/SOCKET, availability and Home
 * Assistant discovery retained, actions from /set only for the sockets of the command role.
 */
@Timeout(60)
class MqttBridgeTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final PluginRegistry REGISTRY = PluginRegistry.discover();

    /**
     * Readings from topic in/level reach socket "level"; socket "say" (a text control input) goes down to topic
     * out/said; socket "secret" has a control input too but is not in the bridge's actions.
     */
    private static String config(Mosquitto broker, int[] ports, String actions) {
        return config(broker.address(), ports, actions);
    }

    private static String config(String broker, int[] ports, String actions) {
        return """
            {"system": "bridge-test", "status": {"port": 0},
             "interfaces": [{"id": "dev", "driver": "mqtt", "address": "%1$s",
               "params": {"readings": [{"channel": "level", "topic": "in/level"}],
                          "commands": [{"channel": "said", "topic": "out/said", "kind": "text"}]}}],
             "methods": [
               {"id": "level-raw", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@dev.level"}, "params": {"kind": "number"}},
               {"id": "level-up", "type": "pass-through", "layer": "processing", "inputs": {"in": "level-raw.out"}, "params": {"kind": "number"}},
               {"id": "level", "type": "pass-through", "layer": "virtual", "inputs": {"in": "level-up.out"}, "params": {"kind": "number"},
                "expose": {"port": %2$d, "name": "level"}},
               {"id": "say", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"}, "params": {"kind": "text", "delivery": "queue"},
                "expose": {"port": %3$d, "name": "say"}},
               {"id": "say-down", "type": "pass-through", "layer": "processing", "inputs": {"in": "say.out"}, "params": {"kind": "text", "delivery": "queue"}},
               {"id": "said", "type": "pass-through", "layer": "sensors_actuators", "inputs": {"in": "say-down.out"}, "params": {"kind": "text", "delivery": "queue"},
                "commands": {"out": "@dev.said"}},
               {"id": "secret", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"}, "params": {"kind": "text"},
                "expose": {"port": %4$d, "name": "secret"}}],
             "bridges": [{"id": "home", "type": "mqtt", "address": "%1$s",
               "params": {"publish": ["level", "say", "secret"], "actions": [%5$s]}}]}
            """.formatted(broker, ports[0], ports[1], ports[2], actions);
    }

    @Test
    void samplesArePublishedAsJsonWithAvailabilityAndDiscoveryAndActionsComeOnlyForTheCommandRole(@TempDir Path tmp)
            throws Exception {
        int[] ports = DaemonProcess.freePorts(3);
        try (Mosquitto broker = Mosquitto.start(tmp)) {
            Path auditLog = tmp.resolve("audit.log");
            Daemon daemon = Daemon.start(new ConfigLoader(REGISTRY).parse(config(broker, ports, "\"say\"")
                    .replaceFirst("\\{", "{\"security\": {\"auditLog\": \"" + auditLog + "\"},")), REGISTRY,
                    EngineClock.system());
            try {
                // The bridge says it is online (retained) once connected.
                assertThat(broker.client(15_000, "mosquitto_sub", "-t", "habla/bridge-test/availability", "-C", "1",
                        "-W", "10").strip()).isEqualTo("online");
                String discovery = broker.client(15_000, "mosquitto_sub", "-t", "homeassistant/#", "-v", "-C", "4",
                        "-W", "10");
                assertThat(discovery).contains("homeassistant/sensor/habla_bridge-test_level_out/config",
                        "\"state_topic\":\"habla/bridge-test/level/out/state\"", "homeassistant/text/habla_bridge-test_say/config");

                // A reading on the device topic comes out of the bridge as the socket's sample line.
                Process sub = broker.subscriber("-t", "habla/bridge-test/level", "-C", "1", "-W", "20");
                try (BufferedReader seen = new BufferedReader(new InputStreamReader(sub.getInputStream(), UTF_8))) {
                    String line = null;
                    for (int i = 0; i < 100 && line == null; i++) {
                        // The subscriber may not be subscribed yet: publish until it has a sample (bounded).
                        broker.publish("in/level", "0.75", false);
                        line = sub.waitFor(100, java.util.concurrent.TimeUnit.MILLISECONDS) ? seen.readLine() : null;
                    }
                    assertThat(line).isNotNull();
                    JsonNode sample = JSON.readTree(line);
                    assertThat(sample.path("type").asText()).isEqualTo("sample");
                    assertThat(sample.path("output").asText()).isEqualTo("out");
                    assertThat(sample.path("value").asDouble()).isEqualTo(0.75);
                    assertThat(sample.path("stale").asBoolean()).isFalse();
                } finally {
                    sub.destroyForcibly();
                }

                // An action for "secret" (not in the command role) is ignored; one for "say" reaches the device.
                broker.publish("ready", "yes", true);
                Process said = broker.subscriber("-t", "ready", "-t", "out/said", "-v", "-C", "2", "-W", "20");
                try (BufferedReader seen = new BufferedReader(new InputStreamReader(said.getInputStream(), UTF_8))) {
                    assertThat(seen.readLine()).isEqualTo("ready yes");
                    broker.publish("habla/bridge-test/secret/set", "open sesame", false);
                    broker.publish("habla/bridge-test/say/set", "hello room", false);
                    assertThat(seen.readLine()).isEqualTo("out/said hello room");
                } finally {
                    said.destroyForcibly();
                }
                // The action taken is in the audit log (the bridge never listens for the other's topic). The bridge
                // writes it after counting the action, and both after the value went into the graph, which may
                // reach the device first: wait for the log line, then read the count.
                long until = System.nanoTime() + 10_000_000_000L;
                while (Files.readAllLines(auditLog).isEmpty() && System.nanoTime() < until) {
                    Thread.sleep(10);
                }
                assertThat(Files.readAllLines(auditLog)).satisfiesExactly(
                        l -> assertThat(l).contains("\"client\":\"mqtt-bridge\"", "\"socket\":\"say\"",
                                "\"value\":\"hello room\"", "\"accepted\":true"));
                JsonNode bridge = daemon.status().path("bridges").get(0);
                assertThat(bridge.path("actions").asLong()).isEqualTo(1);
                try (ControlLines secret = new ControlLines(ports[2])) {
                    secret.send("{\"op\":\"latest\",\"id\":7}");
                    JsonNode answer = secret.next(n -> n.has("id") || n.path("type").asText().equals("sample"),
                            "the answer to latest");
                    assertThat(answer.path("type").asText()).as("secret got no value").isEqualTo("ok");
                }
            } finally {
                daemon.close();
            }
            // Stopped: the bridge said offline, retained, before it left.
            assertThat(broker.client(15_000, "mosquitto_sub", "-t", "habla/bridge-test/availability", "-C", "1",
                    "-W", "10").strip()).isEqualTo("offline");
        }
    }

    @Test
    void anActionWhileASocketClientCommandsIsRefusedAsBusyUntilItReleasesControl(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(3);
        try (Mosquitto broker = Mosquitto.start(tmp)) {
            Daemon daemon = Daemon.start(new ConfigLoader(REGISTRY).parse(config(broker, ports, "\"say\"")), REGISTRY,
                    EngineClock.system());
            try (ControlLines say = new ControlLines(ports[1])) {
                assertThat(broker.client(15_000, "mosquitto_sub", "-t", "habla/bridge-test/availability", "-C", "1",
                        "-W", "10").strip()).isEqualTo("online");
                say.send("{\"op\":\"take\",\"id\":1}"); // commands the socket without sending anything
                say.next(n -> n.path("id").asInt() == 1, "the answer to take");
                broker.publish("ready", "yes", true);
                Process seen = broker.subscriber("-t", "ready", "-t", "habla/bridge-test/say/error", "-t", "out/said",
                        "-v", "-C", "3", "-W", "20");
                try (BufferedReader lines = new BufferedReader(new InputStreamReader(seen.getInputStream(), UTF_8))) {
                    assertThat(lines.readLine()).isEqualTo("ready yes");
                    broker.publish("habla/bridge-test/say/set", "from the bridge", false);
                    String error = lines.readLine();
                    assertThat(error).startsWith("habla/bridge-test/say/error ");
                    JsonNode e = JSON.readTree(error.substring(error.indexOf(' ') + 1));
                    assertThat(e.path("code").asText()).isEqualTo("busy");
                    assertThat(e.path("message").asText()).contains("commanded by say#1");
                    say.send("{\"op\":\"release\",\"id\":2}");
                    say.next(n -> n.path("id").asInt() == 2, "the answer to release");
                    broker.publish("habla/bridge-test/say/set", "from the bridge", false);
                    assertThat(lines.readLine()).isEqualTo("out/said from the bridge");
                } finally {
                    seen.destroyForcibly();
                }
                JsonNode control = say.next(n -> n.path("type").asText().equals("control")
                        && n.path("holder").path("connection").asText().equals("mqtt-bridge"), "the bridge commanding");
                assertThat(control.path("holder").path("address").asText()).isEqualTo(broker.address());
            } finally {
                daemon.close();
            }
        }
    }

    @Test
    void aBridgeNamingASocketNoMethodExposesIsAConfigErrorAtItsPath(@TempDir Path tmp) throws Exception {
        try (Mosquitto broker = Mosquitto.start(tmp)) {
            String bad = config(broker, DaemonProcess.freePorts(3), "\"say\", \"lamp\"");
            try {
                new ConfigLoader(REGISTRY).parse(bad);
                throw new AssertionError("the config was accepted");
            } catch (ConfigException e) {
                assertThat(e.getMessage()).contains("$.bridges[0].params").contains("[lamp]");
            }
        }
    }

    @Test
    void withACredentialsFileABridgeTakesActionsOnlyForTheSocketsTheFileGivesIt(@TempDir Path tmp) throws Exception {
        Path credentials = Files.createFile(tmp.resolve("lab.credentials.json"),
                java.nio.file.attribute.PosixFilePermissions.asFileAttribute(
                        java.nio.file.attribute.PosixFilePermissions.fromString("rw-------")));
        String json = config("127.0.0.1:1883", new int[] {7101, 7102, 7103}, "\"say\"")
                .replaceFirst("\\{", "{\"security\": {\"credentials\": \"lab.credentials.json\"},");
        Files.writeString(credentials, "{\"bridges\": {}}");
        try {
            new ConfigLoader(REGISTRY).parse(json, tmp);
            throw new AssertionError("the config was accepted");
        } catch (ConfigException e) {
            assertThat(e.errors()).singleElement().satisfies(err -> {
                assertThat(err.path()).isEqualTo("$.bridges[0]");
                assertThat(err.message()).contains("bridge 'home' takes actions for [say]");
            });
        }
        Files.writeString(credentials, "{\"bridges\": {\"home\": {\"say\": \"command\"}}}");
        assertThat(new ConfigLoader(REGISTRY).parse(json, tmp).bridges()).hasSize(1);
    }
}
