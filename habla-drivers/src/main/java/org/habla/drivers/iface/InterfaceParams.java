package org.habla.drivers.iface;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.habla.driver.ChannelDescriptor;
import org.habla.plugin.Param;

/**
 * The params of a {@code habla} interface: the channels the config expects the interface program to announce
 * (so the config can be checked before anything connects) and the keep-alive period.
 *
 * <pre>{@code
 * "params": {
 *   "channels": [
 *     {"name": "ir", "direction": "reading", "kind": "vector", "unit": "m"},
 *     {"name": "wheels", "direction": "command", "kind": "vector", "unit": "m/s", "motion": true}
 *   ],
 *   "keepAliveMs": 500
 * }
 * }</pre>
 *
 * @param channels    the channels, at least one; names unique
 * @param keepAliveMs how often HABLA sends {@code {"type":"ping"}} (50..60000 ms)
 */
public record InterfaceParams(
        @Param("the channels the interface program must announce (name, direction, kind, unit, motion, meta)")
        List<ChannelSpec> channels,
        @Param(value = "how often HABLA pings the interface program", unit = "ms", defaultValue = "500",
                min = 50, max = 60_000)
        int keepAliveMs) {

    public InterfaceParams {
        if (channels == null || channels.isEmpty()) {
            throw new IllegalArgumentException("channels: list at least one channel the interface announces");
        }
        channels = List.copyOf(channels);
        Set<String> names = new HashSet<>();
        for (ChannelSpec c : channels) {
            if (!names.add(c.name())) {
                throw new IllegalArgumentException("channels: '" + c.name() + "' is listed twice");
            }
        }
    }

    /** The channels as the engine sees them. */
    public List<ChannelDescriptor> descriptors() {
        return channels.stream().map(ChannelSpec::descriptor).toList();
    }
}
