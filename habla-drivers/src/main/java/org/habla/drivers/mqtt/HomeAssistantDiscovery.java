package org.habla.drivers.mqtt;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Instant;
import java.util.Locale;
import java.util.Map;
import org.habla.net.SampleCodec;
import org.habla.sample.PayloadKind;
import org.habla.sample.Sample;

/**
 * The Home Assistant side of an {@code mqtt} bridge: the discovery configs (single-component payloads, retained)
 * and the per-output state messages they point at.
 *
 * <pre>
 *   PREFIX/sensor/habla_SYS_SOCKET_OUTPUT/config   a sensor per published output:
 *       state_topic  BASE/SYS/SOCKET/OUTPUT/state   {"value":..,"t":"2026-05-01T10:00:00.123Z"}   retained
 *       availability BASE/SYS/availability (online|offline) and BASE/SYS/SOCKET/stale ({"stale":..}), both needed
 *       number   its value; state_class measurement; unit and device_class from the output's unit
 *       text     its value, cut to the 255 characters of an entity's state
 *       record, vector   the time of the value (device_class timestamp); the value itself as the attributes
 *   PREFIX/text/habla_SYS_SOCKET/config            a text entity per action socket: command_topic BASE/SYS/SOCKET/set,
 *       attributes from BASE/SYS/SOCKET/control (who commands the socket)
 * </pre>
 *
 * Entity names are the socket's, with the output's after it when they differ ({@code light}, {@code action lamps});
 * the device is the daemon ({@code HABLA <system>}); {@code default_entity_id} is the unique id with its domain.
 */
final class HomeAssistantDiscovery {

    /** The most characters Home Assistant keeps in an entity's state. */
    static final int MAX_STATE_CHARS = 255;
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;
    /** HABLA's unit names and Home Assistant's, with the device class each measures where it is unambiguous. */
    private static final Map<String, String[]> UNITS = Map.of(
            "degC", new String[] {"°C", "temperature"},
            "K", new String[] {"K", "temperature"},
            "lx", new String[] {"lx", "illuminance"},
            "dB", new String[] {"dB", "sound_pressure"},
            "m", new String[] {"m", "distance"},
            "m/s", new String[] {"m/s", "speed"},
            "W", new String[] {"W", "power"},
            "V", new String[] {"V", "voltage"});

    private final String prefix;
    private final String root;
    private final String system;

    /**
     * @param prefix Home Assistant's discovery prefix
     * @param root   the bridge's topics' first two levels, {@code BASE/SYS}
     * @param system the config's system name
     */
    HomeAssistantDiscovery(String prefix, String root, String system) {
        this.prefix = prefix;
        this.root = root;
        this.system = system;
    }

    /** Whether an output of this kind gets an entity (binary samples do not). */
    static boolean carried(PayloadKind kind) {
        return kind != PayloadKind.AUDIO && kind != PayloadKind.IMAGE;
    }

    /** Where the sensor of a socket's output is configured. */
    String sensorTopic(String socket, String output) {
        return prefix + "/sensor/" + id(socket, output) + "/config";
    }

    /** Where the text entity of an action socket is configured. */
    String textTopic(String socket) {
        return prefix + "/text/" + id(socket, null) + "/config";
    }

    /** Where the newest value of a socket's output is kept (retained) for its sensor. */
    String stateTopic(String socket, String output) {
        return root + "/" + MqttBridge.topicLevel(socket) + "/" + MqttBridge.topicLevel(output) + "/state";
    }

    /** The sensor of one output of a socket with {@code outputs} outputs. */
    ObjectNode sensor(String socket, String output, int outputs, PayloadKind kind, String unit, String version) {
        String id = id(socket, output);
        ObjectNode c = NODES.objectNode().put("name", outputs == 1 || output.equals(socket) ? socket : socket + " "
                + output).put("unique_id", id).put("default_entity_id", "sensor." + entityObjectId(id))
                .put("state_topic", stateTopic(socket, output));
        switch (kind) {
            case NUMBER -> {
                c.put("value_template", "{{ value_json.value }}").put("state_class", "measurement");
                String[] ha = UNITS.get(unit);
                if (ha != null) {
                    c.put("unit_of_measurement", ha[0]).put("device_class", ha[1]);
                } else if (unit != null && !unit.isEmpty()) {
                    c.put("unit_of_measurement", unit);
                }
            }
            case TEXT -> c.put("value_template", "{{ value_json.value[:" + MAX_STATE_CHARS + "] }}");
            default -> c.put("value_template", "{{ value_json.t }}").put("device_class", "timestamp")
                    .put("json_attributes_topic", stateTopic(socket, output))
                    .put("json_attributes_template", kind == PayloadKind.RECORD ? "{{ value_json.value | tojson }}"
                            : "{{ {'values': value_json.value} | tojson }}");
        }
        ArrayNode availability = c.putArray("availability");
        availability.addObject().put("topic", root + "/availability");
        availability.addObject().put("topic", root + "/" + MqttBridge.topicLevel(socket) + "/stale")
                .put("value_template", "{{ 'offline' if value_json.stale else 'online' }}");
        c.put("availability_mode", "all");
        return withDevice(c, version);
    }

    /** The text entity that writes actions to a socket. */
    ObjectNode text(String socket, String version) {
        String id = id(socket, null);
        String level = MqttBridge.topicLevel(socket);
        ObjectNode c = NODES.objectNode().put("name", socket).put("unique_id", id)
                .put("default_entity_id", "text." + entityObjectId(id)).put("command_topic", root + "/" + level + "/set")
                .put("max", MAX_STATE_CHARS).put("mode", "text")
                .put("json_attributes_topic", root + "/" + level + "/control");
        c.putArray("availability").addObject().put("topic", root + "/availability");
        return withDevice(c, version);
    }

    /** The state message of a sample: its value and the time of the reading it came from. */
    static String state(Sample sample) {
        ObjectNode header = SampleCodec.withValue(NODES.objectNode(), sample.payload()).header();
        ObjectNode s = NODES.objectNode();
        s.set("value", header.get("value"));
        long micros = sample.sourceMicros();
        s.put("t", Instant.ofEpochSecond(Math.floorDiv(micros, 1_000_000), Math.floorMod(micros, 1_000_000) * 1_000)
                .toString());
        return s.toString();
    }

    private ObjectNode withDevice(ObjectNode c, String version) {
        ObjectNode device = c.putObject("device");
        device.putArray("identifiers").add("habla_" + MqttBridge.topicLevel(system));
        device.put("name", "HABLA " + system).put("manufacturer", "HABLA").put("model", "HABLA daemon")
                .put("sw_version", version);
        c.putObject("origin").put("name", "HABLA").put("sw_version", version);
        return c;
    }

    private String id(String socket, String output) {
        return "habla_" + MqttBridge.topicLevel(system) + "_" + MqttBridge.topicLevel(socket)
                + (output == null ? "" : "_" + MqttBridge.topicLevel(output));
    }

    /** An entity id's part after the domain: lower-case letters, digits and '_'. */
    private static String entityObjectId(String id) {
        return id.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9_]", "_");
    }
}
