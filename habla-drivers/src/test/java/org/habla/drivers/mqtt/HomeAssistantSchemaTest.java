package org.habla.drivers.mqtt;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;

/** The schema check the discovery tests rely on finds what Home Assistant's documentation forbids. */
class HomeAssistantSchemaTest {

    private static final HomeAssistantSchema SCHEMA = HomeAssistantSchema.load();

    private static JsonNode json(String text) throws Exception {
        return new ObjectMapper().readTree(text);
    }

    @Test
    void aSensorAsTheDocumentationDescribesItPasses() throws Exception {
        assertThat(SCHEMA.violations("sensor", json("""
                {"name": "lux", "unique_id": "x_lux", "default_entity_id": "sensor.x_lux", "state_topic": "a/b",
                 "value_template": "{{ value_json.value }}", "device_class": "illuminance", "unit_of_measurement": "lx",
                 "state_class": "measurement", "availability": [{"topic": "a/availability"},
                 {"topic": "a/stale", "value_template": "{{ 'offline' if value_json.stale else 'online' }}"}],
                 "availability_mode": "all", "device": {"identifiers": ["x"], "name": "X"},
                 "origin": {"name": "HABLA", "sw_version": "1"}}
                """))).isEmpty();
    }

    @Test
    void whatTheDocumentationForbidsIsFound() throws Exception {
        assertThat(SCHEMA.violations("sensor", json("""
                {"name": "t", "object_id": "x", "unique_id": "x", "default_entity_id": "text.x-y",
                 "availability": [{"payload_available": "up"}], "availability_topic": "a",
                 "device_class": "temperature", "unit_of_measurement": "degC", "state_class": "average",
                 "origin": {"sw_version": "1"}, "device": {"name": "X"}, "colour": "red"}
                """))).hasSize(10).anySatisfy(e -> assertThat(e).contains("'state_topic' is required"))
                .anySatisfy(e -> assertThat(e).contains("'object_id' is deprecated"))
                .anySatisfy(e -> assertThat(e).contains("default_entity_id must be 'sensor."))
                .anySatisfy(e -> assertThat(e).contains("availability[0]: 'topic' is required"))
                .anySatisfy(e -> assertThat(e).contains("availability and availability_topic exclude"))
                .anySatisfy(e -> assertThat(e).contains("unit \"degC\" does not go with device_class temperature"))
                .anySatisfy(e -> assertThat(e).contains("state_class must be one of"))
                .anySatisfy(e -> assertThat(e).contains("origin: 'name' is required"))
                .anySatisfy(e -> assertThat(e).contains("device: one of [\"identifiers\",\"connections\"]"))
                .anySatisfy(e -> assertThat(e).contains("unknown key 'colour'"));
        assertThat(SCHEMA.violations("text", json("{\"command_topic\": \"a/set\", \"max\": 1000}")))
                .singleElement().satisfies(e -> assertThat(e).contains("max is out of range"));
        assertThat(SCHEMA.violations("sensor", json("""
                {"state_topic": "a", "device_class": "timestamp", "state_class": "measurement"}
                """))).singleElement().satisfies(e -> assertThat(e).contains("a timestamp sensor has no state_class"));
    }
}
