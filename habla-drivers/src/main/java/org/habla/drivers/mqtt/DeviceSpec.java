package org.habla.drivers.mqtt;

import org.habla.plugin.Param;

/**
 * A device on the broker whose availability topic says whether it is there: Zigbee2MQTT's
 * {@code zigbee2mqtt/<name>/availability} ({@code online}/{@code offline}, or {@code {"state":"online"}}), or a
 * Home Assistant style {@code availability_topic} with its own payloads. A device reached through another one
 * names it in {@code via}: Zigbee2MQTT's devices are reached through its bridge, whose state topic
 * ({@code zigbee2mqtt/bridge/state}) is the only one its last will covers.
 */
public record DeviceSpec(
        @Param("the device's name, as the readings and commands name it") String name,
        @Param("the topic its availability is published on") String availabilityTopic,
        @Param(value = "the payload (or the JSON \"state\" field) that means it is there", defaultValue = "\"online\"")
        String online,
        @Param(value = "the payload (or the JSON \"state\" field) that means it is gone", defaultValue = "\"offline\"")
        String offline,
        @Param(value = "the device this one is reached through (a Zigbee2MQTT bridge, a hub): while it is offline, so "
                + "is this one; empty: none", defaultValue = "\"\"") String via) {

    public DeviceSpec {
        if (name == null || name.isBlank() || availabilityTopic == null) {
            throw new IllegalArgumentException("devices: every device needs a \"name\" and an \"availabilityTopic\"");
        }
        TopicFilter.topic(availabilityTopic);
        if (online.equals(offline)) {
            throw new IllegalArgumentException("devices: '" + name + "' has the same online and offline payload");
        }
    }
}
