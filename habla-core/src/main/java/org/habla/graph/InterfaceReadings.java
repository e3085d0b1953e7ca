package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Driver;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What comes in on one interface: a producer per reading channel (the {@code link} channel among them), the sink its
 * connections decode into — a reading on an unknown channel or of the wrong kind is counted and dropped — the
 * devices the driver says are unavailable, and the facts it learnt about the robot.
 */
final class InterfaceReadings {

    private static final Logger LOG = LoggerFactory.getLogger(InterfaceReadings.class);

    private final String interfaceId;
    private final Map<String, ChannelDescriptor> channels;
    private final Map<String, Producer> ports = new HashMap<>();
    /** The handle a session writes each reading channel through, made once; the engine's own link is not one. */
    private final Map<String, ReadingSink.Channel> handles = new HashMap<>();
    private final Map<String, String> unavailable = new ConcurrentHashMap<>();
    /** The devices the driver told of, by name, sorted for the status. */
    private final Map<String, DeviceState> devices = new java.util.concurrent.ConcurrentSkipListMap<>();
    /** Whether the engine tells the {@code link} record, or the driver's connections deliver it (a recording). */
    private final boolean engineTellsLink;
    private final EngineClock clock;
    private final LinkStates states;
    private final Sink sink = new Sink();
    private final LongAdder malformed = new LongAdder();
    private final LongAdder unknownChannel = new LongAdder();
    private volatile ObjectNode robotInfo = JsonNodeFactory.instance.objectNode();

    /** @param channels every channel of the interface, the {@code link} channel included */
    InterfaceReadings(String interfaceId, Map<String, ChannelDescriptor> channels, boolean engineTellsLink,
            EngineClock clock, LinkStates states) {
        this.interfaceId = interfaceId;
        this.channels = channels;
        this.engineTellsLink = engineTellsLink;
        this.clock = clock;
        this.states = states;
        for (ChannelDescriptor c : channels.values()) {
            if (c.direction() == ChannelDescriptor.Direction.READING) {
                Producer port = new Producer("@" + interfaceId + "." + c.name());
                ports.put(c.name(), port);
                if (!engineTellsLink || !Driver.LINK_CHANNEL.name().equals(c.name())) {
                    handles.put(c.name(), new Handle(c, port));
                }
            }
        }
    }

    /** Where the interface's connections put what they decode. */
    ReadingSink sink() {
        return sink;
    }

    /** The producer of a reading channel; null if there is none. */
    Producer port(String channel) {
        return ports.get(channel);
    }

    Set<String> channels() {
        return ports.keySet();
    }

    /** Why a reading channel's device is unavailable now (its link being up), or null when it is available. */
    String unavailable(String channel) {
        return unavailable.get(channel);
    }

    /** A fresh session tells its devices' availability again: until it does, every device is available. */
    void forgetAvailability() {
        unavailable.clear();
        devices.clear();
    }

    /** What a driver last said of one device, and since when (engine clock, µs). */
    private record DeviceState(boolean online, String detail, long sinceMicros) {
    }

    ObjectNode robotInfo() {
        return robotInfo;
    }

    /** Adds the counts of dropped input to an interface's status. */
    void countsTo(ObjectNode status) {
        status.put("malformed", malformed.sum());
        status.put("unknownChannel", unknownChannel.sum());
    }

    /**
     * Adds the devices the driver told of and the unavailable channels, if any, and how many readings each channel
     * published to the status.
     */
    void publishedTo(ObjectNode status) {
        if (!devices.isEmpty()) {
            ObjectNode ds = status.putObject("devices");
            devices.forEach((name, d) -> ds.putObject(name).put("online", d.online()).put("detail", d.detail())
                    .put("sinceMicros", d.sinceMicros()));
        }
        if (!unavailable.isEmpty()) {
            ObjectNode un = status.putObject("unavailable");
            unavailable.forEach(un::put);
        }
        ObjectNode rs = status.putObject("readings");
        ports.forEach((name, port) -> rs.put(name, port.published()));
    }

    /** A declared reading channel as a session writes it: its producer and kind, found once. */
    private final class Handle implements ReadingSink.Channel {
        private final ChannelDescriptor descriptor;
        private final Producer port;

        Handle(ChannelDescriptor descriptor, Producer port) {
            this.descriptor = descriptor;
            this.port = port;
        }

        @Override
        public void publish(Payload value) {
            publish(value, clock.nowMicros());
        }

        @Override
        public void publish(Payload value, long sourceMicros) {
            if (!descriptor.kind().accepts(value.kind())) {
                sink.malformed("reading on " + descriptor.name() + " is " + value.kind().wireName() + ", expected "
                        + descriptor.kind().wireName());
                return;
            }
            port.publish(value, sourceMicros, false);
        }
    }

    /** What is written to a channel the interface does not have: counted and dropped. */
    private final class Unknown implements ReadingSink.Channel {
        private final String name;

        Unknown(String name) {
            this.name = name;
        }

        @Override
        public void publish(Payload value) {
            publish(value, 0);
        }

        @Override
        public void publish(Payload value, long sourceMicros) {
            unknownChannel.increment();
            LOG.debug("interface {}: reading on unknown channel '{}' ignored", interfaceId, name);
        }
    }

    /** Turns what the sessions decode into samples on the reading channels. */
    private final class Sink implements ReadingSink {
        @Override
        public Channel channel(String name) {
            Channel handle = handles.get(name);
            return handle != null ? handle : new Unknown(name);
        }

        @Override
        public void malformed(String what) {
            malformed.increment();
            long n = malformed.sum();
            if (n <= 10 || n % 1000 == 0) {
                LOG.warn("interface {}: malformed input dropped ({} so far): {}", interfaceId, n, what);
            }
        }

        @Override
        public void availability(String channel, boolean available, String why) {
            if (!ports.containsKey(channel) || Driver.LINK_CHANNEL.name().equals(channel)) {
                unknownChannel.increment();
                return;
            }
            // The device's state and the staleness it causes change as one step, like a link's.
            states.locked(() -> {
                String before = available ? unavailable.remove(channel) : unavailable.put(channel, why);
                if ((before == null) != available) {
                    LOG.info("interface {}: the device of channel {} is {} ({})", interfaceId, channel,
                            available ? "available again" : "unavailable", why);
                    states.refreshStaleness();
                }
            });
        }

        @Override
        public void device(String device, boolean online, String detail) {
            DeviceState before = devices.get(device);
            if (before != null && before.online() == online && before.detail().equals(detail)) {
                return;
            }
            long since = before != null && before.online() == online ? before.sinceMicros() : clock.nowMicros();
            devices.put(device, new DeviceState(online, detail, since));
            if (before == null ? !online : before.online() != online) {
                LOG.info("interface {}: device {} is {} ({})", interfaceId, device, online ? "online" : "offline",
                        detail);
            }
        }

        @Override
        public void robotInfo(ObjectNode info) {
            ObjectNode merged = robotInfo.deepCopy();
            merged.setAll(info.deepCopy());
            robotInfo = merged;
            LOG.info("interface {}: robot {}", interfaceId, merged);
        }
    }
}
