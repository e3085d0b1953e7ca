package org.habla.drivers.mqtt;

import static java.nio.charset.StandardCharsets.UTF_8;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.util.concurrent.TimeUnit;
import org.habla.config.ConfigLoader;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.Mosquitto;

/**
 * A small daemon with an {@code mqtt} bridge for the bridge's tests, and the waits they share (each bounded):
 * reading {@code level} (number, from topic in/level), {@code state} (record, from in/state), {@code say} (a text
 * action that goes down to topic out/said) and {@code secret} (a text socket no bridge writes to).
 */
final class BridgeRoom {

    static final PluginRegistry REGISTRY = PluginRegistry.discover();

    private BridgeRoom() {
    }

    /** The config, with {@code top} spliced in at the top level and {@code bridge} in the bridge's params. */
    static String config(Mosquitto broker, int[] ports, String top, String bridge) {
        return config(broker, ports, top, bridge, "");
    }

    /** The same, with {@code entry} spliced in after the bridge's params ({@code , "reconnect": {..}}). */
    static String config(Mosquitto broker, int[] ports, String top, String bridge, String entry) {
        return """
            {"system": "bridge-test", "status": {"port": 0}, %6$s
             "interfaces": [{"id": "dev", "driver": "mqtt", "address": "%1$s",
               "params": {"readings": [{"channel": "level", "topic": "in/level"},
                                       {"channel": "state", "topic": "in/state", "kind": "record"}],
                          "commands": [{"channel": "said", "topic": "out/said", "kind": "text"}]}}],
             "methods": [
               {"id": "level-raw", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@dev.level"}, "params": {"kind": "number"}},
               {"id": "level-up", "type": "pass-through", "layer": "processing", "inputs": {"in": "level-raw.out"}, "params": {"kind": "number"}},
               {"id": "level", "type": "pass-through", "layer": "virtual", "inputs": {"in": "level-up.out"}, "params": {"kind": "number"},
                "expose": {"port": %2$d, "name": "level"}},
               {"id": "state-raw", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@dev.state"}, "params": {"kind": "record"}},
               {"id": "state-up", "type": "pass-through", "layer": "processing", "inputs": {"in": "state-raw.out"}, "params": {"kind": "record"}},
               {"id": "state", "type": "pass-through", "layer": "virtual", "inputs": {"in": "state-up.out"}, "params": {"kind": "record"},
                "expose": {"port": %5$d, "name": "state"}},
               {"id": "say", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"}, "params": {"kind": "text", "delivery": "queue"},
                "expose": {"port": %3$d, "name": "say"}},
               {"id": "say-down", "type": "pass-through", "layer": "processing", "inputs": {"in": "say.out"}, "params": {"kind": "text", "delivery": "queue"}},
               {"id": "said", "type": "pass-through", "layer": "sensors_actuators", "inputs": {"in": "say-down.out"}, "params": {"kind": "text", "delivery": "queue"},
                "commands": {"out": "@dev.said"}},
               {"id": "secret", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"}, "params": {"kind": "text"},
                "expose": {"port": %4$d, "name": "secret"}}],
             "bridges": [{"id": "home", "type": "mqtt", "address": "%1$s",
               "params": {"publish": ["level", "state", "say", "secret"], "actions": ["say"] %7$s}%8$s}]}
            """.formatted(broker.address(), ports[0], ports[1], ports[2], ports[3], top, bridge, entry);
    }

    static Daemon start(String config) throws Exception {
        return Daemon.start(new ConfigLoader(REGISTRY).parse(config), REGISTRY, EngineClock.system());
    }

    /** Waits until the bridge has said it is online (a daemon stopped before left "offline" retained). */
    static void awaitOnline(Mosquitto broker) throws IOException {
        Process sub = broker.subscriber("-t", "habla/bridge-test/availability", "-W", "15");
        try (BufferedReader seen = new BufferedReader(new InputStreamReader(sub.getInputStream(), UTF_8))) {
            for (String line = seen.readLine(); line != null; line = seen.readLine()) {
                if (line.equals("online")) {
                    return;
                }
            }
            throw new AssertionError("the bridge did not say it is online within 15 s");
        } finally {
            sub.destroyForcibly();
        }
    }

    /**
     * Publishes {@code payload} on {@code topic} until {@code watched} carries a message (the bridge may not have
     * subscribed yet), and returns that first message of {@code watched} with its topic.
     */
    static String publishUntilSeen(Mosquitto broker, String topic, String payload, String watched) throws Exception {
        Process sub = broker.subscriber("-t", watched, "-v", "-C", "1", "-W", "20");
        try (BufferedReader seen = new BufferedReader(new InputStreamReader(sub.getInputStream(), UTF_8))) {
            for (int i = 0; i < 100 && !sub.waitFor(100, TimeUnit.MILLISECONDS); i++) {
                broker.publish(topic, payload, false);
            }
            return seen.readLine();
        } finally {
            sub.destroyForcibly();
        }
    }

    /** The one retained message on {@code topic}, waiting for it (bounded); null if none came. */
    static String retained(Mosquitto broker, String topic) throws Exception {
        for (int i = 0; i < 50; i++) {
            String out = broker.client(10_000, "mosquitto_sub", "-t", topic, "--retained-only", "-C", "1", "-W", "1")
                    .strip();
            if (!out.isEmpty() && !out.equals("Timed out")) {
                return out;
            }
        }
        return null;
    }
}
