package org.habla.drivers.mqtt;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.habla.sample.NumberValue;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.Test;

/** Every discovery config the bridge can make, checked against Home Assistant's documented schema. */
class HomeAssistantDiscoveryTest {

    private static final HomeAssistantSchema SCHEMA = HomeAssistantSchema.load();
    private final HomeAssistantDiscovery discovery = new HomeAssistantDiscovery("homeassistant", "habla/room", "room");

    @Test
    void everyKindAndUnitMakesASensorHomeAssistantAccepts() {
        String[] units = {"", "degC", "K", "lx", "dB", "m", "m/s", "W", "V", "%", "rad"};
        for (PayloadKind kind : new PayloadKind[] {PayloadKind.NUMBER, PayloadKind.TEXT, PayloadKind.RECORD,
                PayloadKind.VECTOR}) {
            for (String unit : units) {
                ObjectNode c = discovery.sensor("light-level", "lux", 2, kind, unit, "development");
                assertThat(SCHEMA.violations("sensor", c)).as(kind + " " + unit + ": " + c).isEmpty();
            }
        }
        assertThat(SCHEMA.violations("text", discovery.text("action", "development"))).isEmpty();
    }

    @Test
    void aSensorIsAvailableOnlyWhileTheDaemonIsOnlineAndItsSocketFreshAndNamedOnce() {
        ObjectNode c = discovery.sensor("occupancy", "occupancy", 1, PayloadKind.RECORD, "", "development");
        assertThat(c.path("name").asText()).isEqualTo("occupancy");
        assertThat(discovery.sensor("action", "lamps", 3, PayloadKind.RECORD, "", "x").path("name").asText())
                .isEqualTo("action lamps");
        assertThat(c.path("default_entity_id").asText()).isEqualTo("sensor.habla_room_occupancy_occupancy");
        assertThat(c.path("availability_mode").asText()).isEqualTo("all");
        assertThat(c.path("availability").findValuesAsText("topic"))
                .containsExactly("habla/room/availability", "habla/room/occupancy/stale");
        assertThat(c.path("json_attributes_topic").asText()).isEqualTo("habla/room/occupancy/occupancy/state");
        assertThat(c.path("origin").path("name").asText()).isEqualTo("HABLA");
        ObjectNode lux = discovery.sensor("light", "lux", 1, PayloadKind.NUMBER, "lx", "development");
        assertThat(lux.path("device_class").asText()).isEqualTo("illuminance");
        assertThat(lux.path("state_class").asText()).isEqualTo("measurement");
        assertThat(lux.path("unit_of_measurement").asText()).isEqualTo("lx");
    }

    @Test
    void aStateMessageCarriesTheValueAndTheTimeOfItsReading() throws Exception {
        JsonNode number = new ObjectMapper().readTree(HomeAssistantDiscovery.state(
                new Sample(new NumberValue(312.5), "light", 7, 1_700_000_000_123_456L, false)));
        assertThat(number.path("value").asDouble()).isEqualTo(312.5);
        assertThat(number.path("t").asText()).isEqualTo("2023-11-14T22:13:20.123456Z");
        JsonNode record = new ObjectMapper().readTree(HomeAssistantDiscovery.state(new Sample(
                RecordValue.builder().put("desk", true).build(), "occupancy", 8, 1_700_000_000_000_000L, false)));
        assertThat(record.path("value").path("desk").asBoolean()).isTrue();
    }
}
