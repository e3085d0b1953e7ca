package org.habla.drivers.mqtt;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Path;
import java.util.function.Predicate;
import org.habla.daemon.Daemon;
import org.habla.testing.DaemonProcess;
import org.habla.testing.Mosquitto;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Actions through the bridge against a real Mosquitto broker: never from a retained message, and under the rule
 * of one commander at a time with the bridge letting go as a client does, also on a socket without a watchdog.
 */
@Timeout(90)
class MqttBridgeControlTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @Test
    void aRetainedActionIsNeverTakenAtAnyStartOfTheDaemon(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(4);
        try (Mosquitto broker = Mosquitto.start(tmp)) {
            broker.publish("habla/bridge-test/say/set", "forward", true);
            String config = BridgeRoom.config(broker, ports, "", "");
            for (int start = 1; start <= 2; start++) {
                try (Daemon daemon = BridgeRoom.start(config)) {
                    BridgeRoom.awaitOnline(broker);
                    String first = BridgeRoom.publishUntilSeen(broker, "habla/bridge-test/say/set", "live " + start,
                            "out/said");
                    assertThat(first).as("start " + start).isEqualTo("out/said live " + start);
                    JsonNode bridge = daemon.status().path("bridges").get(0);
                    assertThat(bridge.path("retainedIgnored").asLong()).isEqualTo(1);
                }
            }
        }
    }

    @Test
    void withoutAWatchdogTheBridgeLetsGoAfterItsHoldAndTakesAndReleasesControlLikeAClient(@TempDir Path tmp)
            throws Exception {
        int[] ports = DaemonProcess.freePorts(4);
        try (Mosquitto broker = Mosquitto.start(tmp);
                Daemon daemon = BridgeRoom.start(BridgeRoom.config(broker, ports, "\"safety\": {\"watchdogMs\": 0},",
                        ", \"holdMs\": 300"));
                ControlLines say = new ControlLines(ports[1])) {
            BridgeRoom.awaitOnline(broker);
            assertThat(BridgeRoom.publishUntilSeen(broker, "habla/bridge-test/say/set", "from the bridge", "out/said"))
                    .isEqualTo("out/said from the bridge");

            // Busy while the bridge holds the socket, then the client's write takes it: the hold lapsed.
            String answer = "busy";
            for (int id = 1; answer.equals("busy") && id < 500; id++) {
                say.send("{\"value\": \"from a client\", \"id\": " + id + "}");
                int want = id;
                answer = say.next(n -> n.path("id").asInt() == want, "the answer to write " + id).path("code")
                        .asText("ok");
                if (answer.equals("busy")) {
                    Thread.sleep(20);
                }
            }
            assertThat(answer).isEqualTo("ok");
            JsonNode control = JSON.readTree(BridgeRoom.retained(broker, "habla/bridge-test/say/control"));
            assertThat(control.path("holder").path("connection").asText()).startsWith("say#");
            assertThat(control.path("why").asText()).contains("mqtt-bridge", "was silent for");

            // The client holds for ever (no watchdog): the bridge takes control, acts, and gives it back.
            String error = BridgeRoom.publishUntilSeen(broker, "habla/bridge-test/say/set", "refused",
                    "habla/bridge-test/say/error");
            assertThat(JSON.readTree(error.substring(error.indexOf(' ') + 1)).path("code").asText()).isEqualTo("busy");
            broker.publish("habla/bridge-test/say/take", "", false);
            say.next(isControl(h -> h.path("connection").asText().equals("mqtt-bridge")), "the bridge taking control");
            assertThat(BridgeRoom.retained(broker, "habla/bridge-test/say/control")).contains("\"mqtt-bridge\"");
            assertThat(BridgeRoom.publishUntilSeen(broker, "habla/bridge-test/say/set", "taken", "out/said"))
                    .isEqualTo("out/said taken");
            broker.publish("habla/bridge-test/say/release", "", false);
            JsonNode released = say.next(n -> n.path("type").asText().equals("control") && n.path("holder").isNull(),
                    "control released");
            assertThat(released.path("why").asText()).contains("released by mqtt-bridge");
            assertThat(daemon.status().path("bridges").get(0).path("commands")).isEmpty();
        }
    }

    @Test
    void theBridgeLosingItsBrokerGivesUpTheControlItHeld(@TempDir Path tmp) throws Exception {
        int[] ports = DaemonProcess.freePorts(4);
        try (Mosquitto broker = Mosquitto.start(tmp);
                Daemon daemon = BridgeRoom.start(BridgeRoom.config(broker, ports, "\"safety\": {\"watchdogMs\": 0},",
                        ", \"holdMs\": 3600000"));
                ControlLines say = new ControlLines(ports[1])) {
            BridgeRoom.awaitOnline(broker);
            assertThat(BridgeRoom.publishUntilSeen(broker, "habla/bridge-test/say/set", "forward", "out/said"))
                    .isEqualTo("out/said forward");
            say.next(isControl(h -> h.path("connection").asText().equals("mqtt-bridge")), "the bridge commanding");
            assertThat(daemon.status().path("bridges").get(0).path("commands").toString()).contains("say");
            broker.stop();
            JsonNode left = say.next(n -> n.path("type").asText().equals("control") && n.path("holder").isNull(),
                    "control given up");
            assertThat(left.path("why").asText()).contains("mqtt-bridge", "disconnected");
        }
    }

    private static Predicate<JsonNode> isControl(Predicate<JsonNode> holder) {
        return n -> n.path("type").asText().equals("control") && !n.path("holder").isNull()
                && holder.test(n.path("holder"));
    }
}
