package org.habla.drivers.mqtt;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.habla.driver.Driver;
import org.habla.plugin.Param;

/**
 * The params of an {@code mqtt} interface: how to reach the broker, and the mapping of topics to channels.
 *
 * <pre>{@code
 * "params": {
 *   "version": "5",
 *   "devices":  [{"name": "hall_motion", "availabilityTopic": "zigbee2mqtt/hall_motion/availability"}],
 *   "readings": [{"channel": "motion_hall", "topic": "zigbee2mqtt/hall_motion", "field": "occupancy",
 *                 "device": "hall_motion"}],
 *   "commands": [{"channel": "lamp_hall", "topic": "zigbee2mqtt/hall_lamp/set", "kind": "record"}]
 * }
 * }</pre>
 */
public record MqttParams(
        @Param(value = "the MQTT protocol version: \"5\" or \"3.1.1\"", defaultValue = "\"5\"") String version,
        @Param(value = "the client identifier; empty: habla- and a random suffix", defaultValue = "\"\"")
        String clientId,
        @Param(value = "the user name to log in with; empty: none", defaultValue = "\"\"") String username,
        @Param(value = "the password; prefer passwordFile, which keeps it out of the config", defaultValue = "\"\"")
        String password,
        @Param(value = "a file whose first line is the password", defaultValue = "\"\"", file = true)
        String passwordFile,
        @Param(value = "connect with TLS (the default port is then 8883)", defaultValue = "false") boolean tls,
        @Param(value = "a PEM file of the certificate authorities that sign the broker's certificate; empty: the "
                + "JVM's trust store", defaultValue = "\"\"", file = true) String caFile,
        @Param(value = "how often client and broker check each other when nothing flows; a silent broker is lost "
                + "after about 1.5 times this", unit = "s", defaultValue = "5",
                min = 1, max = MAX_KEEP_ALIVE_S)
        int keepAliveS,
        @Param(value = "the quality of service of the subscriptions: 0 or 1", defaultValue = "0") int subscribeQos,
        @Param(value = "messages received and not yet decoded; more are dropped and counted", defaultValue = "1024",
                min = 1, max = MAX_QUEUE_MESSAGES)
        int queueMessages,
        @Param(value = "devices with an availability topic (name, availabilityTopic, online, offline)",
                defaultValue = "[]") List<DeviceSpec> devices,
        @Param(value = "reading channels (channel, topic, field, kind, unit, device, values)", defaultValue = "[]")
        List<ReadingMap> readings,
        @Param(value = "command channels (channel, topic, kind, unit, template, qos, device, motion)",
                defaultValue = "[]") List<CommandMap> commands) {

    /** The longest keep-alive MQTT allows: 65 535 s. */
    public static final int MAX_KEEP_ALIVE_S = 65_535;
    /** The most messages an interface may hold undecoded. */
    public static final int MAX_QUEUE_MESSAGES = 65_536;

    public MqttParams {
        BrokerEndpoint.MqttVersion.fromConfig(version);
        if (!password.isEmpty() && !passwordFile.isEmpty()) {
            throw new IllegalArgumentException("give password or passwordFile, not both");
        }
        if (!caFile.isEmpty() && !tls) {
            throw new IllegalArgumentException("caFile is for TLS: set \"tls\": true as well");
        }
        if (subscribeQos != 0 && subscribeQos != 1) {
            throw new IllegalArgumentException("subscribeQos must be 0 or 1, was " + subscribeQos);
        }
        devices = List.copyOf(devices);
        readings = List.copyOf(readings);
        commands = List.copyOf(commands);
        if (readings.isEmpty() && commands.isEmpty()) {
            throw new IllegalArgumentException("readings, commands: map at least one topic to a channel");
        }
        Set<String> deviceNames = new HashSet<>();
        for (DeviceSpec d : devices) {
            if (!deviceNames.add(d.name())) {
                throw new IllegalArgumentException("devices: '" + d.name() + "' is listed twice");
            }
        }
        for (DeviceSpec d : devices) {
            through(devices, d);
        }
        Set<String> channels = new HashSet<>();
        for (ReadingMap r : readings) {
            unique(channels, r.channel());
            known(deviceNames, r.device(), r.channel());
        }
        for (CommandMap c : commands) {
            unique(channels, c.channel());
            known(deviceNames, c.device(), c.channel());
        }
    }

    /** A device's via names a listed device, and following via never comes back to it. */
    private static void through(List<DeviceSpec> devices, DeviceSpec d) {
        String name = d.via();
        for (int hops = 0; !name.isEmpty(); hops++) {
            String current = name;
            DeviceSpec next = devices.stream().filter(x -> x.name().equals(current)).findFirst().orElse(null);
            if (next == null) {
                throw new IllegalArgumentException("devices: '" + d.name() + "' is reached via '" + current
                        + "', which is not in \"devices\"");
            }
            if (next.name().equals(d.name()) || hops > devices.size()) {
                throw new IllegalArgumentException("devices: the via chain of '" + d.name() + "' goes round in a circle");
            }
            name = next.via();
        }
    }

    private static void unique(Set<String> channels, String channel) {
        if (Driver.LINK_CHANNEL.name().equals(channel)) {
            throw new IllegalArgumentException("'link' is the engine's own channel; name the channel otherwise");
        }
        if (!channels.add(channel)) {
            throw new IllegalArgumentException("channel '" + channel + "' is mapped twice");
        }
    }

    private static void known(Set<String> devices, String device, String channel) {
        if (!device.isEmpty() && !devices.contains(device)) {
            throw new IllegalArgumentException("channel '" + channel + "' names device '" + device
                    + "', which is not in \"devices\"");
        }
    }

    BrokerEndpoint.MqttVersion mqttVersion() {
        return BrokerEndpoint.MqttVersion.fromConfig(version);
    }
}
