package org.habla.drivers.iface;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Locale;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Driver;
import org.habla.plugin.Param;
import org.habla.sample.PayloadKind;

/**
 * One channel an interface program must announce, as written in the config and in the program's hello:
 * <pre>{@code {"name": "ir", "direction": "reading", "kind": "vector", "unit": "m", "motion": false, "meta": {...}}}</pre>
 */
public record ChannelSpec(
        @Param("the channel's name, as in \"@interface.name\"") String name,
        @Param("\"reading\" (robot to HABLA) or \"command\" (HABLA to robot)") String direction,
        @Param("the payload kind: number, vector, text, record, audio or image") String kind,
        @Param(value = "the SI unit of its numbers", defaultValue = "\"\"") String unit,
        @Param(value = "true for a command that moves the robot (dropped while the link is down, stopped by the watchdog)",
                defaultValue = "false") boolean motion,
        @Param(value = "facts general methods need, e.g. sensor poses", defaultValue = "{}") ObjectNode meta) {

    public ChannelSpec {
        meta = meta.deepCopy();
        if (name == null) {
            throw new IllegalArgumentException("name: every channel needs a name");
        }
        if (Driver.LINK_CHANNEL.name().equals(name)) {
            throw new IllegalArgumentException("name: 'link' is the engine's own channel and cannot be announced");
        }
        descriptor(name, direction, kind, unit, motion, meta);
    }

    /** The channel as the engine sees it. */
    public ChannelDescriptor descriptor() {
        return descriptor(name, direction, kind, unit, motion, meta);
    }

    private static ChannelDescriptor descriptor(String name, String direction, String kind, String unit,
            boolean motion, ObjectNode meta) {
        ChannelDescriptor.Direction dir;
        if ("reading".equals(direction)) {
            dir = ChannelDescriptor.Direction.READING;
        } else if ("command".equals(direction)) {
            dir = ChannelDescriptor.Direction.COMMAND;
        } else {
            throw new IllegalArgumentException("direction: channel '" + name + "' has direction '" + direction
                    + "' (expected \"reading\" or \"command\")");
        }
        PayloadKind k;
        try {
            k = PayloadKind.fromWire(kind == null ? "" : kind);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("kind: channel '" + name + "': " + e.getMessage());
        }
        if (k == PayloadKind.ANY) {
            throw new IllegalArgumentException("kind: channel '" + name + "' must have one kind, not 'any'");
        }
        return new ChannelDescriptor(name, dir, k, unit, motion, meta);
    }

    /** The direction as written on the wire. */
    static String wireName(ChannelDescriptor.Direction direction) {
        return direction.name().toLowerCase(Locale.ROOT);
    }
}
