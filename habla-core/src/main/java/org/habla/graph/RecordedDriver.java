package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import org.habla.config.InterfaceConfig;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Driver;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;

/**
 * A recorded interface as a driver: the channels the recording describes, and one connection, {@code recording},
 * through which a replay feeds the recorded readings and link changes in, each as the robot's driver delivered it.
 * The interface link takes them exactly as a live driver's: a reading goes through the same sink, a link change
 * makes the interface go up or down and what depends on it stale. The recorded {@code link} records are readings
 * like the others (the driver lists the channel), so the engine tells none of its own. The connection carries
 * every command channel and absorbs a command while the recording has the link up (it counts as written), and
 * refuses it while the link is down.
 *
 * <p>Fed from one thread, the replay's; the graph reads the link's state from any.
 */
final class RecordedDriver implements InterfaceDriver {

    static final String CONNECTION = "recording";

    private final List<ChannelDescriptor> channels = new ArrayList<>();
    private final Set<String> commandChannels;
    private RecordedLink link;

    RecordedDriver(List<ChannelDescriptor> recorded) {
        for (ChannelDescriptor c : recorded) {
            if (!c.name().equals(Driver.LINK_CHANNEL.name())) {
                channels.add(c);
            }
        }
        channels.add(Driver.LINK_CHANNEL);
        commandChannels = channels.stream().filter(c -> c.direction() == ChannelDescriptor.Direction.COMMAND)
                .map(ChannelDescriptor::name).collect(Collectors.toUnmodifiableSet());
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return List.copyOf(channels);
    }

    @Override
    public List<Link> connections(InterfaceConfig config, ReadingSink sink, Runnable changed) {
        if (link != null) {
            throw new IllegalStateException("a recorded interface feeds one interface link");
        }
        link = new RecordedLink(commandChannels, sink, changed);
        return List.of(link);
    }

    /** A recorded reading (the engine's {@code link} records included), delivered as the driver's session did. */
    void reading(String channel, Payload value, long sourceMicros) {
        connected().sink.reading(channel, value, sourceMicros);
    }

    /** A recorded link change: the interface goes up or down as it did. */
    void link(boolean up) {
        RecordedLink l = connected();
        if (l.up != up) {
            l.up = up;
            l.changed.run();
        }
    }

    private RecordedLink connected() {
        if (link == null) {
            throw new IllegalStateException("the recorded interface has no interface link yet");
        }
        return link;
    }

    /** The one connection of a recorded interface: up and down as the recording says, writing nothing. */
    private static final class RecordedLink implements Link {
        private final Set<String> commandChannels;
        private final ReadingSink sink;
        private final Runnable changed;
        private volatile boolean up;

        RecordedLink(Set<String> commandChannels, ReadingSink sink, Runnable changed) {
            this.commandChannels = commandChannels;
            this.sink = sink;
            this.changed = changed;
        }

        @Override
        public String connectionName() {
            return CONNECTION;
        }

        @Override
        public Set<String> commandChannels() {
            return commandChannels;
        }

        @Override
        public boolean up() {
            return up;
        }

        @Override
        public String lastError() {
            return "";
        }

        @Override
        public void start() {
        }

        @Override
        public void stop() {
        }

        @Override
        public CommandResult command(String channel, Payload value) {
            return up ? CommandResult.WRITTEN : CommandResult.DOWN;
        }

        @Override
        public boolean stopMotion() {
            return up;
        }

        @Override
        public ObjectNode status() {
            ObjectNode n = JsonNodeFactory.instance.objectNode();
            n.put("name", CONNECTION);
            n.put("up", up);
            n.put("replayed", true);
            return n;
        }
    }
}
