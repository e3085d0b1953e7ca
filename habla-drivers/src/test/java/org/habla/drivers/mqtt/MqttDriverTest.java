package org.habla.drivers.mqtt;

import static org.assertj.core.api.Assertions.assertThat;

import static java.nio.charset.StandardCharsets.UTF_8;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
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
 * The {@code mqtt} driver in a running daemon against a real Mosquitto broker, with {@code mosquitto_pub} and
 * {@code mosquitto_sub} as the devices: topics mapped to channels, availability as staleness, commands from
 * templates and never retained, and a broker restart survived.
 */
@Timeout(60)
class MqttDriverTest {

    private static final PluginRegistry REGISTRY = PluginRegistry.discover();

    /**
     * A room on the broker: a motion sensor (JSON field, availability), a Tasmota-style thermometer (nested field),
     * a raw number topic, a wildcard text topic, and a lamp command. Each reading reaches its own socket through
     * three pass-through methods; the lamp takes values from a socket.
     */
    private static String config(Mosquitto broker, String version, int[] ports) {
        return """
            {"system": "mqtt-test",
             "status": {"port": 0},
             "interfaces": [{"id": "room", "driver": "mqtt", "address": "%s",
               "reconnect": {"initialMs": 100, "maxMs": 400},
               "params": {"version": "%s", "keepAliveS": 2,
                 "devices": [{"name": "z2m", "availabilityTopic": "z2m/bridge/state"},
                             {"name": "hall_motion", "availabilityTopic": "z2m/hall_motion/availability", "via": "z2m"},
                             {"name": "hall_lamp", "availabilityTopic": "z2m/hall_lamp/availability", "via": "z2m"}],
                 "readings": [
                   {"channel": "motion", "topic": "z2m/hall_motion", "field": "occupancy", "device": "hall_motion"},
                   {"channel": "hall_lux", "topic": "z2m/hall_motion", "field": "illuminance", "unit": "lx", "device": "hall_motion"},
                   {"channel": "temperature", "topic": "tele/kitchen/SENSOR", "field": "AM2301.Temperature", "unit": "degC"},
                   {"channel": "lux", "topic": "sensors/+/lux"},
                   {"channel": "words", "topic": "words/#", "kind": "text"}],
                 "commands": [{"channel": "lamp", "topic": "z2m/hall_lamp/set", "kind": "number",
                               "template": "{\\"state\\": \\"ON\\", \\"brightness\\": {{value}}}", "device": "hall_lamp"}]}}],
             "methods": [%s]}
            """.formatted(broker.address(), version, String.join(",\n", methods(ports)));
    }

    private static List<String> methods(int[] ports) {
        List<String> m = new ArrayList<>();
        String[][] readings = {{"motion", "number"}, {"temperature", "number"}, {"lux", "number"}, {"words", "text"}};
        for (int i = 0; i < readings.length; i++) {
            String ch = readings[i][0];
            String kind = readings[i][1];
            m.add(relay(ch + "-raw", "sensors_actuators", "@room." + ch, kind, ""));
            m.add(relay(ch + "-up", "processing", ch + "-raw.out", kind, ""));
            m.add(relay(ch, "virtual", ch + "-up.out", kind,
                    ", \"expose\": {\"port\": " + ports[i] + ", \"name\": \"" + ch + "\"}"));
        }
        m.add(relay("lamp-in", "virtual", "control", "number",
                ", \"expose\": {\"port\": " + ports[4] + ", \"name\": \"lamp\"}"));
        m.add(relay("lamp-down", "processing", "lamp-in.out", "number", ""));
        m.add(relay("lamp", "sensors_actuators", "lamp-down.out", "number", ", \"commands\": {\"out\": \"@room.lamp\"}"));
        return m;
    }

    private static String relay(String id, String layer, String source, String kind, String more) {
        return "{\"id\": \"" + id + "\", \"type\": \"pass-through\", \"layer\": \"" + layer + "\", \"inputs\": {\"in\": \""
                + source + "\"}, \"params\": {\"kind\": \"" + kind + "\", \"delivery\": \"queue\"}" + more + "}";
    }

    private static Daemon daemon(Mosquitto broker, String version, int[] ports) throws Exception {
        return Daemon.start(new ConfigLoader(REGISTRY).parse(config(broker, version, ports)), REGISTRY,
                EngineClock.system());
    }

    @Test
    void readingsFollowTheMappingFromJsonFieldsNestedFieldsRawPayloadsAndWildcards(@TempDir Path tmp)
            throws Exception {
        int[] ports = DaemonProcess.freePorts(5);
        try (Mosquitto broker = Mosquitto.start(tmp); Daemon daemon = daemon(broker, "5", ports);
                ControlLines motion = new ControlLines(ports[0]); ControlLines temperature = new ControlLines(ports[1]);
                ControlLines lux = new ControlLines(ports[2]); ControlLines words = new ControlLines(ports[3])) {
            motion.staleness(false);

            broker.publish("z2m/hall_motion", "{\"occupancy\":true,\"illuminance\":310,\"battery\":97}", false);
            broker.publish("tele/kitchen/SENSOR", "{\"Time\":\"2026-11-25T10:00:00\",\"AM2301\":{\"Temperature\":21.5,"
                    + "\"Humidity\":40.1}}", false);
            broker.publish("sensors/desk/lux", "412.5", false);
            broker.publish("words/teacher/said", "lights on", false);

            assertThat(motion.nextOfType("sample").path("value").asDouble()).isEqualTo(1.0);
            assertThat(temperature.nextOfType("sample").path("value").asDouble()).isEqualTo(21.5);
            assertThat(lux.nextOfType("sample").path("value").asDouble()).isEqualTo(412.5);
            assertThat(words.nextOfType("sample").path("value").asText()).isEqualTo("lights on");

            // A state without the field is no reading; a payload that is not JSON is counted as malformed, once
            // although it feeds two channels (motion and hall_lux).
            broker.publish("z2m/hall_motion", "{\"battery\":96}", false);
            broker.publish("z2m/hall_motion", "not json", false);
            broker.publish("z2m/hall_motion", "{\"occupancy\":false}", false);
            JsonNode next = motion.nextOfType("sample");
            assertThat(next.path("value").asDouble()).isEqualTo(0.0);
            assertThat(daemon.status().path("interfaces").get(0).path("malformed").asLong()).isEqualTo(1);
        }
    }

    @Test
    void aDeviceThatGoesOfflineMakesItsChannelsStaleAndItsCommandsAreDroppedUntilItIsBack(@TempDir Path tmp)
            throws Exception {
        int[] ports = DaemonProcess.freePorts(5);
        try (Mosquitto broker = Mosquitto.start(tmp); Daemon daemon = daemon(broker, "5", ports);
                ControlLines motion = new ControlLines(ports[0]); ControlLines lux = new ControlLines(ports[2])) {
            motion.staleness(false);
            lux.staleness(false);
            broker.publish("z2m/hall_motion/availability", "offline", true);
            JsonNode notice = motion.staleness(true);
            assertThat(notice.path("why").asText()).contains("@room.motion").contains("hall_motion is offline");

            // Another device's channel stays fresh.
            broker.publish("sensors/desk/lux", "100", false);
            assertThat(lux.nextOfType("sample").path("stale").asBoolean()).isFalse();

            // Zigbee2MQTT 2.x says it in JSON.
            broker.publish("z2m/hall_motion/availability", "{\"state\":\"online\"}", true);
            motion.staleness(false);
            broker.publish("z2m/hall_motion", "{\"occupancy\":true}", false);
            assertThat(motion.nextOfType("sample").path("stale").asBoolean()).isFalse();
        }
    }

    @Test
    void aZigbee2MqttBridgeLeavingByItsLastWillMakesEveryDeviceReachedThroughItStale(@TempDir Path tmp)
            throws Exception {
        int[] ports = DaemonProcess.freePorts(5);
        try (Mosquitto broker = Mosquitto.start(tmp); Daemon daemon = daemon(broker, "5", ports);
                ControlLines motion = new ControlLines(ports[0]); ControlLines lux = new ControlLines(ports[2])) {
            motion.staleness(false);
            // Zigbee2MQTT as a real client: its bridge says online and leaves a last will; its devices say online.
            broker.publish("z2m/bridge/request/health", "{}", true);
            Process z2m = broker.subscriber("-i", "zigbee2mqtt", "-t", "z2m/bridge/request/#", "--will-topic",
                    "z2m/bridge/state", "--will-payload", "{\"state\":\"offline\"}", "--will-retain");
            try (BufferedReader said = new BufferedReader(new InputStreamReader(z2m.getInputStream(), UTF_8))) {
                assertThat(said.readLine()).as("connected, with its will").isEqualTo("{}");
                broker.publish("z2m/bridge/state", "{\"state\":\"online\"}", true);
                broker.publish("z2m/hall_motion/availability", "{\"state\":\"online\"}", true);
            } finally {
                z2m.destroyForcibly().waitFor(); // dies without a goodbye: the broker publishes its will
            }
            JsonNode notice = motion.staleness(true);
            assertThat(notice.path("why").asText()).contains("z2m is offline", "hall_motion is reached through z2m");
            broker.publish("sensors/desk/lux", "100", false);
            assertThat(lux.nextOfType("sample").path("stale").asBoolean()).as("no device: not stale").isFalse();
            broker.publish("z2m/bridge/state", "{\"state\":\"online\"}", true);
            motion.staleness(false);
        }
    }

    @Test
    void commandsArePublishedFromTheirTemplateAndNeverRetainedOverMqtt311(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(5);
        try (Mosquitto broker = Mosquitto.start(tmp); Daemon daemon = daemon(broker, "3.1.1", ports);
                ControlLines motion = new ControlLines(ports[0]); ControlLines lamp = new ControlLines(ports[4])) {
            motion.staleness(false);
            broker.publish("ready", "yes", true);
            Process sub = broker.subscriber("-t", "ready", "-t", "z2m/hall_lamp/set", "-v", "-C", "2", "-W", "20");
            try (BufferedReader seen = new BufferedReader(new InputStreamReader(sub.getInputStream(), UTF_8))) {
                assertThat(seen.readLine()).as("the subscriber is subscribed").isEqualTo("ready yes");
                lamp.send("{\"value\": 128, \"id\": 1}");
                assertThat(lamp.nextOfType("ok").path("id").asInt()).isEqualTo(1);
                assertThat(seen.readLine()).isEqualTo("z2m/hall_lamp/set {\"state\": \"ON\", \"brightness\": 128}");
            } finally {
                sub.destroyForcibly();
            }
            // Nothing retained on the command topic: a new subscriber that asks for retained messages only gets the
            // retained sentinel, not the command.
            broker.publish("sentinel", "here", true);
            String retained = broker.client(10_000, "mosquitto_sub", "-t", "z2m/hall_lamp/set", "-t", "sentinel",
                    "--retained-only", "-v", "-W", "1");
            assertThat(retained).contains("sentinel here").doesNotContain("z2m/hall_lamp/set");

            // A command to a device that is offline is dropped and counted.
            broker.publish("z2m/hall_lamp/availability", "offline", true);
            long dropped = daemon.status().path("interfaces").get(0).path("commandsDropped").asLong();
            awaitDropped(daemon, lamp, dropped);
        }
    }

    @Test
    void theLinkSurvivesABrokerRestartStaleMeanwhileAndFreshAfter(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(5);
        try (Mosquitto broker = Mosquitto.start(tmp); Daemon daemon = daemon(broker, "5", ports);
                ControlLines lux = new ControlLines(ports[2])) {
            lux.staleness(false);
            broker.stop();
            assertThat(lux.staleness(true).path("why").asText()).contains("interface room is down");
            broker.startAgain();
            lux.staleness(false);
            broker.publish("sensors/desk/lux", "250", false);
            JsonNode fresh = lux.nextOfType("sample");
            assertThat(fresh.path("value").asDouble()).isEqualTo(250);
            assertThat(fresh.path("stale").asBoolean()).isFalse();
            assertThat(daemon.status().path("interfaces").get(0).path("connections").get(0).path("connects").asLong())
                    .isEqualTo(2);
        }
    }

    /** Writes to the lamp until the daemon counts a dropped command (the offline notice may come later). */
    private static void awaitDropped(Daemon daemon, ControlLines lamp, long before) throws Exception {
        long deadline = System.nanoTime() + 10_000_000_000L;
        for (int id = 100; System.nanoTime() < deadline; id++) {
            lamp.send("{\"value\": 10, \"id\": " + id + "}");
            lamp.nextOfType("ok");
            long until = System.nanoTime() + 500_000_000L;
            while (System.nanoTime() < until) {
                if (daemon.status().path("interfaces").get(0).path("commandsDropped").asLong() > before) {
                    return;
                }
                Thread.onSpinWait();
            }
        }
        throw new AssertionError("a command to the offline lamp was not dropped");
    }
}
