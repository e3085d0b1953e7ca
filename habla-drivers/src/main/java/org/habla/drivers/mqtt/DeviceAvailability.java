package org.habla.drivers.mqtt;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Which devices of a broker connection can be reached: a device is unreachable while its own availability topic
 * says it is offline, or while the device it is reached through ({@code via}: a Zigbee2MQTT bridge, a hub) is.
 *
 * <pre>
 *   zigbee2mqtt/bridge/state   offline  ──▶  zigbee2mqtt (the bridge) offline
 *                                             ├── desk_motion  unreachable (via zigbee2mqtt)
 *                                             └── desk_lamp    unreachable (via zigbee2mqtt)
 * </pre>
 *
 * Zigbee2MQTT's last will covers only its bridge's state topic: when the bridge process dies, each device's
 * availability topic keeps saying online, so only the {@code via} chain makes its devices stale. Every device is
 * taken to be there until it says otherwise. Thread-safe: the reader thread writes, the engine's writers read.
 */
final class DeviceAvailability {

    private final Map<String, DeviceSpec> devices = new LinkedHashMap<>();
    /** Why a device said it is offline, by name; absent while it has not. */
    private final Map<String, String> offline = new HashMap<>();

    DeviceAvailability(List<DeviceSpec> specs) {
        specs.forEach(d -> devices.put(d.name(), d));
    }

    /** Records what a device's availability topic said. */
    synchronized void said(DeviceSpec d, boolean online, String why) {
        if (online) {
            offline.remove(d.name());
        } else {
            offline.put(d.name(), why);
        }
    }

    /** Why {@code device} cannot be reached now, or null when it can (or is no listed device). */
    synchronized String unreachable(String device) {
        String name = device;
        // The config refuses a via cycle; the bound keeps a bad table from looping.
        for (int hops = 0; hops <= devices.size() && name != null && !name.isEmpty(); hops++) {
            String why = offline.get(name);
            if (why != null) {
                return name.equals(device) ? why : why + ", and " + device + " is reached through " + name;
            }
            DeviceSpec d = devices.get(name);
            name = d == null ? null : d.via();
        }
        return null;
    }
}
