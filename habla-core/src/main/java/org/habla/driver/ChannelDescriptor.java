package org.habla.driver;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Objects;
import java.util.regex.Pattern;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordLayout;

/**
 * One named channel of an interface: readings that come up from the robot, or commands that go
 * down to it.
 *
 * @param name      the channel name, used in configs as {@code "@interface.name"}
 * @param direction reading or command
 * @param kind      the payload kind
 * @param unit      the SI unit of numbers ({@code "m"}, {@code "rad"}, {@code "m/s"}), empty if none
 * @param motion    true for commands that move the robot: dropped while the link is down, stopped
 *                  by the watchdog
 * @param metadata  facts of this robot that general methods need (e.g. sonar poses), as JSON
 * @param layout    for a record channel whose values are a typed form, that form's fields; null otherwise
 */
public record ChannelDescriptor(String name, Direction direction, PayloadKind kind, String unit, boolean motion,
        ObjectNode metadata, RecordLayout<?> layout) {

    private static final Pattern NAME = Pattern.compile("[A-Za-z][A-Za-z0-9_-]{0,63}");

    public enum Direction { READING, COMMAND }

    public ChannelDescriptor {
        if (name == null || !NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("channel name '" + name + "' must be a letter then letters, digits, '_' or '-'");
        }
        Objects.requireNonNull(direction, "direction");
        Objects.requireNonNull(kind, "kind");
        unit = unit == null ? "" : unit;
        if (motion && direction != Direction.COMMAND) {
            throw new IllegalArgumentException("only a command channel can be a motion channel: " + name);
        }
        metadata = metadata == null ? JsonNodeFactory.instance.objectNode() : metadata.deepCopy();
        if (layout != null && kind != PayloadKind.RECORD) {
            throw new IllegalArgumentException("only a record channel has a record layout: " + name);
        }
    }

    public ChannelDescriptor(String name, Direction direction, PayloadKind kind, String unit, boolean motion,
            ObjectNode metadata) {
        this(name, direction, kind, unit, motion, metadata, null);
    }

    public static ChannelDescriptor reading(String name, PayloadKind kind, String unit) {
        return new ChannelDescriptor(name, Direction.READING, kind, unit, false, null);
    }

    public static ChannelDescriptor command(String name, PayloadKind kind, String unit, boolean motion) {
        return new ChannelDescriptor(name, Direction.COMMAND, kind, unit, motion, null);
    }

    /** A copy with {@code metadata}. */
    public ChannelDescriptor withMetadata(ObjectNode metadata) {
        return new ChannelDescriptor(name, direction, kind, unit, motion, metadata, layout);
    }

    /** A copy whose record values are the form {@code layout} describes. */
    public ChannelDescriptor withLayout(RecordLayout<?> layout) {
        return new ChannelDescriptor(name, direction, kind, unit, motion, metadata, layout);
    }

    /** A copy of the metadata. */
    @Override
    public ObjectNode metadata() {
        return metadata.deepCopy();
    }
}
