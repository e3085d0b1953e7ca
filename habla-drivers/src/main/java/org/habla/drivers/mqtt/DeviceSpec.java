package org.habla.drivers.mqtt;

import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;

/**
 * A device on the broker whose availability topic says whether it is there: Zigbee2MQTT's
 * {@code zigbee2mqtt/<name>/availability} ({@code online}/{@code offline}, or {@code {"state":"online"}}), or a
 * Home Assistant style {@code availability_topic} with its own payloads.
 */
public record DeviceSpec(
        @Param("the device's name, as the readings and commands name it") String name,
        @Param("the topic its availability is published on") String availabilityTopic,
        @Param(value = "the payload (or the JSON \"state\" field) that means it is there", defaultValue = "\"online\"")
        String online,
        @Param(value = "the payload (or the JSON \"state\" field) that means it is gone", defaultValue = "\"offline\"")
        String offline) {

    public DeviceSpec {
        online = ParamDefaults.or(DeviceSpec.class, "online", online);
        offline = ParamDefaults.or(DeviceSpec.class, "offline", offline);
        if (name == null || name.isBlank() || availabilityTopic == null) {
            throw new IllegalArgumentException("devices: every device needs a \"name\" and an \"availabilityTopic\"");
        }
        TopicFilter.topic(availabilityTopic);
        if (online.equals(offline)) {
            throw new IllegalArgumentException("devices: '" + name + "' has the same online and offline payload");
        }
    }
}
