package org.habla.drivers.mqtt;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Path;
import java.util.function.Predicate;
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
 * What {@code habla status} learns from the {@code mqtt} driver against a real Mosquitto broker: each device with
 * its availability, the method made stale by an offline sensor with its channel and device, and a command to an
 * offline lamp dropped for that reason rather than as a broker link down.
 */
@Timeout(60)
class MqttDeviceStatusTest {

    private static final PluginRegistry REGISTRY = PluginRegistry.discover();
    private static final long WAIT_MS = 15_000;

    private static Daemon daemon(Mosquitto broker, int[] ports) throws Exception {
        String json = """
            {"system": "mqtt-status", "status": {"port": %d}, "safety": {"watchdogMs": 0},
             "interfaces": [{"id": "room", "driver": "mqtt", "address": "%s",
               "params": {"devices": [
                   {"name": "hall_motion", "availabilityTopic": "z2m/hall_motion/availability"},
                   {"name": "hall_lamp", "availabilityTopic": "z2m/hall_lamp/availability"}],
                 "readings": [{"channel": "motion", "topic": "z2m/hall_motion", "field": "occupancy",
                               "device": "hall_motion"}],
                 "commands": [{"channel": "lamp", "topic": "z2m/hall_lamp/set", "kind": "number",
                               "template": "{{value}}", "device": "hall_lamp"}]}}],
             "methods": [
               %s, %s, %s,
               %s, %s, %s]}
            """.formatted(ports[2], broker.address(),
                relay("motion-raw", "sensors_actuators", "@room.motion", ""),
                relay("motion-up", "processing", "motion-raw.out", ""),
                relay("motion", "virtual", "motion-up.out", ", \"expose\": {\"port\": " + ports[0] + "}"),
                relay("lamp-in", "virtual", "control", ", \"expose\": {\"port\": " + ports[1] + ", \"name\": \"lamp\"}"),
                relay("lamp-down", "processing", "lamp-in.out", ""),
                relay("lamp", "sensors_actuators", "lamp-down.out", ", \"commands\": {\"out\": \"@room.lamp\"}"));
        return Daemon.start(new ConfigLoader(REGISTRY).parse(json), REGISTRY, EngineClock.system());
    }

    private static String relay(String id, String layer, String source, String more) {
        return "{\"id\": \"" + id + "\", \"type\": \"pass-through\", \"layer\": \"" + layer + "\", \"inputs\": {\"in\": \""
                + source + "\"}, \"params\": {\"kind\": \"number\", \"delivery\": \"queue\"}" + more + "}";
    }

    @Test
    void theStatusNamesTheOfflineDeviceAndWhatItMadeStale(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(3);
        try (Mosquitto broker = Mosquitto.start(tmp); Daemon daemon = daemon(broker, ports);
                ControlLines motion = new ControlLines(ports[0])) {
            motion.staleness(false);
            broker.publish("z2m/hall_motion/availability", "online", true);
            await(daemon, st -> room(st).path("devices").path("hall_motion").path("online").asBoolean(), "online");

            broker.publish("z2m/hall_motion/availability", "offline", true);
            JsonNode st = await(daemon, x -> method(x, "motion").path("stale").asBoolean(), "motion stale");
            JsonNode device = room(st).path("devices").path("hall_motion");
            assertThat(device.path("online").asBoolean(true)).isFalse();
            assertThat(device.path("detail").asText()).isEqualTo("z2m/hall_motion/availability says offline");
            JsonNode because = method(st, "motion").path("staleBecause");
            assertThat(because.path("source").asText()).isEqualTo("@room.motion");
            assertThat(because.path("why").asText()).contains("hall_motion is offline");

            java.io.StringWriter out = new java.io.StringWriter();
            int code = new picocli.CommandLine(new org.habla.cli.StatusCommand()).setOut(new java.io.PrintWriter(out))
                    .execute("--port", "" + daemon.statusPort());
            assertThat(code).isZero();
            assertThat(out.toString().lines()).anySatisfy(l -> assertThat(l)
                    .matches("hall_motion +room +OFFLINE +z2m/hall_motion/availability says offline"));
            assertThat(out.toString().lines()).anySatisfy(l -> assertThat(l)
                    .matches("motion-raw +@room\\.motion +the device of @room\\.motion is unavailable: .*"));
        }
    }

    @Test
    void aCommandToAnOfflineDeviceIsDroppedNamingTheDevice(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(3);
        try (Mosquitto broker = Mosquitto.start(tmp); Daemon daemon = daemon(broker, ports);
                ControlLines lamp = new ControlLines(ports[1])) {
            await(daemon, st -> room(st).path("up").asBoolean(), "the broker link up");
            broker.publish("z2m/hall_lamp/availability", "offline", true);
            await(daemon, st -> room(st).path("devices").has("hall_lamp"), "the lamp reported");
            lamp.send("{\"value\": 10, \"id\": 1}");
            lamp.nextOfType("ok");
            JsonNode st = await(daemon, x -> room(x).path("commandsDropped").asLong() == 1, "the command dropped");
            assertThat(room(st).path("lastDrop").path("channel").asText()).isEqualTo("lamp");
            assertThat(room(st).path("lastDrop").path("why").asText())
                    .isEqualTo("device hall_lamp cannot be reached: hall_lamp is offline (z2m/hall_lamp/availability says offline)");
            assertThat(room(st).path("up").asBoolean()).isTrue();
        }
    }

    private static JsonNode room(JsonNode status) {
        return status.path("interfaces").get(0);
    }

    private static JsonNode method(JsonNode status, String id) {
        for (JsonNode m : status.path("methods")) {
            if (m.path("id").asText().equals(id)) {
                return m;
            }
        }
        throw new AssertionError("no method " + id);
    }

    private static JsonNode await(Daemon daemon, Predicate<JsonNode> condition, String what) throws Exception {
        long end = System.nanoTime() + WAIT_MS * 1_000_000L;
        JsonNode st = daemon.status();
        while (!condition.test(st) && System.nanoTime() < end) {
            Thread.sleep(10);
            st = daemon.status();
        }
        assertThat(condition.test(st)).as(what + " in " + st).isTrue();
        return st;
    }
}
