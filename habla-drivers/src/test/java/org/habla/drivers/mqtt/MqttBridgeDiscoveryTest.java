package org.habla.drivers.mqtt;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import org.habla.daemon.Daemon;
import org.habla.testing.DaemonProcess;
import org.habla.testing.Mosquitto;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Home Assistant discovery from a running daemon's bridge, read back from a real Mosquitto broker: every config
 * valid for its component as Home Assistant documents it, states and staleness retained for a Home Assistant that
 * starts later, and everything said again when Home Assistant says it is online.
 */
@Timeout(90)
class MqttBridgeDiscoveryTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final HomeAssistantSchema SCHEMA = HomeAssistantSchema.load();
    /** One sensor per published output (level, state, say, secret) and one text entity per action socket (say). */
    private static final int CONFIGS = 5;

    @Test
    void everyDiscoveryConfigIsValidForItsComponentAndPointsAtRetainedStatesAndStaleness(@TempDir Path tmp)
            throws Exception {
        int[] ports = DaemonProcess.freePorts(4);
        try (Mosquitto broker = Mosquitto.start(tmp); Daemon daemon = BridgeRoom.start(BridgeRoom.config(broker, ports,
                "", ""))) {
            BridgeRoom.awaitOnline(broker);
            Map<String, JsonNode> configs = new HashMap<>();
            for (String line : broker.client(15_000, "mosquitto_sub", "-t", "homeassistant/+/+/config", "-v", "-C",
                    Integer.toString(CONFIGS), "-W", "10").strip().split("\n")) {
                configs.put(line.substring(0, line.indexOf(' ')), JSON.readTree(line.substring(line.indexOf(' ') + 1)));
            }
            assertThat(configs).hasSize(CONFIGS);
            configs.forEach((topic, config) -> {
                String component = topic.split("/")[1];
                assertThat(SCHEMA.violations(component, config)).as(topic + ": " + config).isEmpty();
                assertThat(config.has("origin") && config.has("device") && config.has("default_entity_id")).isTrue();
                String name = config.path("name").asText();
                assertThat(name.split(" ")).as("a name said twice: " + name).doesNotHaveDuplicates();
            });
            JsonNode record = configs.get("homeassistant/sensor/habla_bridge-test_state_out/config");
            assertThat(record.path("json_attributes_topic").asText()).isEqualTo("habla/bridge-test/state/out/state");
            JsonNode level = configs.get("homeassistant/sensor/habla_bridge-test_level_out/config");
            assertThat(level.path("availability").findValuesAsText("topic")).contains("habla/bridge-test/level/stale");

            // A value and the staleness are kept on the broker for a Home Assistant that starts later.
            assertThat(BridgeRoom.publishUntilSeen(broker, "in/state", "{\"desk\": true}",
                    "habla/bridge-test/state/out/state")).contains("\"value\":{\"desk\":true}");
            assertThat(BridgeRoom.retained(broker, "habla/bridge-test/state/out/state")).contains("\"desk\":true");
            assertThat(JSON.readTree(BridgeRoom.retained(broker, "habla/bridge-test/level/stale")).path("stale")
                    .asBoolean()).isFalse();

            // Home Assistant starting again (its birth message) has every config said again.
            broker.publish("homeassistant/sensor/habla_bridge-test_level_out/config", "", true);
            String again = BridgeRoom.publishUntilSeen(broker, "homeassistant/status", "online",
                    "homeassistant/sensor/habla_bridge-test_level_out/config");
            assertThat(again).contains("\"unique_id\":\"habla_bridge-test_level_out\"");
        }
    }
}
