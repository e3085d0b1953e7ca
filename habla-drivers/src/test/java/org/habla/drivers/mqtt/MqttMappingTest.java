package org.habla.drivers.mqtt;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Map;
import java.util.Optional;
import org.habla.config.ParamsJson;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

/** Topic filters, readings from payloads and command payloads from templates, in memory. */
class MqttMappingTest {

    private static Optional<Payload> read(String field, String kind, String payload) {
        return new ReadingDecoder(new ReadingMap("ch", "t/#", field, kind, null, null,
                kind.equals("number") ? Map.of("Open", 2.0) : Map.of()))
                .decode(payload.getBytes(UTF_8));
    }

    @Test
    void aDeviceIsReachedThroughAListedDeviceAndNeverThroughItself() {
        String devices = "{\"readings\": [{\"channel\": \"m\", \"topic\": \"z/m\", \"device\": \"m\"}], \"devices\": [%s]}";
        String ok = devices.formatted("{\"name\": \"z\", \"availabilityTopic\": \"z/bridge/state\"},"
                + "{\"name\": \"m\", \"availabilityTopic\": \"z/m/availability\", \"via\": \"z\"}");
        var mapper = new com.fasterxml.jackson.databind.ObjectMapper();
        org.assertj.core.api.Assertions.assertThatCode(() -> ParamsJson.of(MqttParams.class, ok))
                .doesNotThrowAnyException();
        assertThatThrownBy(() -> ParamsJson.of(MqttParams.class, devices.formatted(
                "{\"name\": \"m\", \"availabilityTopic\": \"z/m/availability\", \"via\": \"hub\"}"))).hasStackTraceContaining("'m' is reached via 'hub', which is not in \"devices\"");
        assertThatThrownBy(() -> ParamsJson.of(MqttParams.class, devices.formatted(
                "{\"name\": \"a\", \"availabilityTopic\": \"a/s\", \"via\": \"m\"},"
                + "{\"name\": \"m\", \"availabilityTopic\": \"m/s\", \"via\": \"a\"}")))
                .hasStackTraceContaining("goes round in a circle");
    }

    @Test
    void wildcardsMatchOneLevelOrTheRest() {
        assertThat(new TopicFilter("zigbee2mqtt/+/availability").matches("zigbee2mqtt/desk_lamp/availability")).isTrue();
        assertThat(new TopicFilter("zigbee2mqtt/+/availability").matches("zigbee2mqtt/a/b/availability")).isFalse();
        assertThat(new TopicFilter("tele/#").matches("tele")).isTrue();
        assertThat(new TopicFilter("tele/#").matches("tele/kitchen/SENSOR")).isTrue();
        assertThat(new TopicFilter("a/b").matches("a/b/c")).isFalse();
        assertThatThrownBy(() -> new TopicFilter("a/#/b")).hasMessageContaining("'#' alone in the last level");
        assertThatThrownBy(() -> TopicFilter.topic("a/+/set")).hasMessageContaining("wildcard");
    }

    @Test
    void readingsComeFromFieldsNestedFieldsOrTheWholePayload() {
        assertThat(read("occupancy", "number", "{\"occupancy\":true}")).contains(new NumberValue(1));
        assertThat(read("AM2301.Temperature", "number", "{\"AM2301\":{\"Temperature\":21.5}}")).contains(new NumberValue(21.5));
        assertThat(read("", "number", " 412.5\n")).contains(new NumberValue(412.5));
        assertThat(read("", "number", "OFF")).contains(new NumberValue(0));
        assertThat(read("", "number", "Open")).as("the values map").contains(new NumberValue(2));
        assertThat(read("", "text", "lights on")).contains(new TextValue("lights on"));
        assertThat(read("", "vector", "[1, 2.5]")).contains(VectorValue.of(1, 2.5));
        assertThat(read("", "record", "{\"state\":\"ON\"}")).contains(RecordValue.builder().put("state", "ON").build());
        assertThat(read("battery", "number", "{\"occupancy\":true}")).as("no such field: no reading").isEmpty();
    }

    @Test
    void payloadsThatAreNotTheKindAreRefused() {
        assertThatThrownBy(() -> read("occupancy", "number", "not json")).hasMessageContaining("not a JSON object");
        assertThatThrownBy(() -> read("", "number", "maybe")).hasMessageContaining("is not a number");
        assertThatThrownBy(() -> read("x", "record", "{\"x\":3}")).hasMessageContaining("not a JSON object");
    }

    @Test
    void templatesFillTheCommandAndRefuseAMissingField() {
        assertThat(new PayloadTemplate("{\"brightness\": {{value}}}").render(new NumberValue(128)))
                .isEqualTo("{\"brightness\": 128}");
        assertThat(new PayloadTemplate("{{value}}").render(new NumberValue(0.25))).isEqualTo("0.25");
        assertThat(new PayloadTemplate("{\"state\": \"{{value}}\"}").render(new TextValue("OFF")))
                .isEqualTo("{\"state\": \"OFF\"}");
        assertThat(new PayloadTemplate("{{state}}/{{ level }}").render(RecordValue.builder().put("state", "ON")
                .put("level", 3.0).build())).isEqualTo("ON/3");
        assertThat(new PayloadTemplate("{{value}}").render(VectorValue.of(1, 0.5))).isEqualTo("[1,0.5]");
        assertThatThrownBy(() -> new PayloadTemplate("{{state}}").render(RecordValue.builder().build()))
                .hasMessageContaining("needs field 'state'");
        assertThatThrownBy(() -> new PayloadTemplate("{{value}}").render(new NumberValue(Double.NaN)))
                .hasMessageContaining("finite");
    }
}
