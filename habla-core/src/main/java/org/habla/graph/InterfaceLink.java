package org.habla.graph;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.Consumer;
import org.habla.config.InterfaceConfig;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Driver;
import org.habla.driver.ReadingSink;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.VectorValue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One robot interface in the running graph: its driver's connections, a producer per reading
 * channel (plus the engine's {@code link} channel), and the routing of commands to the connection
 * that carries them. Motion commands are dropped — never delayed — while their connection is down
 * or the motion watchdog has tripped.
 *
 * <p>A watchdog trip leaves a stop <em>owed</em> on every connection that carries a motion channel. It is
 * paid at once from a thread of its own and, at the latest, just before the next motion command on that
 * connection, under one lock: a new motion never reaches the robot ahead of the stop, and a stop that could
 * not be written while the connection was down is written before the first motion after it comes back.
 *
 * <p>What the interface runs on is its {@link InterfaceDriver}: a robot's driver or a recording, taken the same
 * way. A recording sees the interface at its edges: its reading channels' ports, what {@link #command} says became
 * of a command, and the link changes {@link #onLinkChange} tells.
 */
final class InterfaceLink {

    private static final Logger LOG = LoggerFactory.getLogger(InterfaceLink.class);

    private final InterfaceConfig config;
    private final EngineClock clock;
    private final Map<String, ChannelDescriptor> channels = new HashMap<>();
    private final Map<String, OutputPort> readings = new HashMap<>();
    private final Map<String, String> unavailable = new java.util.concurrent.ConcurrentHashMap<>();
    private final Map<String, Link> commandRoutes = new HashMap<>();
    private final List<Link> connections;
    private final LinkStates states;
    /** Whether the engine tells the {@code link} record, or the driver's connections deliver it (a recording). */
    private final boolean engineTellsLink;
    private final Sink sink = new Sink();
    private final LongAdder malformed = new LongAdder();
    private final LongAdder unknownChannel = new LongAdder();
    private final LongAdder commandsSent = new LongAdder();
    private final AtomicLong commandsDropped = new AtomicLong();
    private final AtomicLong droppedMoves = new AtomicLong();
    private final Object motionLock = new Object();
    private final Set<Link> stopsOwed = new HashSet<>();
    private volatile ObjectNode robotInfo = JsonNodeFactory.instance.objectNode();
    private volatile MotionWatchdog watchdog;
    private volatile Consumer<Boolean> linkChanges = up -> { };
    private volatile boolean up;
    /** When the link last went up or down (engine clock, µs); its start until the first change. */
    private volatile long sinceMicros;
    private AutoCloseable linkTicker;

    InterfaceLink(InterfaceConfig config, InterfaceDriver driver, EngineClock clock, LinkStates states) {
        this.states = states;
        this.config = config;
        this.clock = clock;
        List<ChannelDescriptor> described = driver.channels();
        this.engineTellsLink = described.stream().noneMatch(c -> c.name().equals(Driver.LINK_CHANNEL.name()));
        for (ChannelDescriptor c : described) {
            channels.put(c.name(), c);
        }
        channels.put(Driver.LINK_CHANNEL.name(), Driver.LINK_CHANNEL);
        for (ChannelDescriptor c : channels.values()) {
            if (c.direction() == ChannelDescriptor.Direction.READING) {
                readings.put(c.name(), new OutputPort("@" + config.id() + "." + c.name()));
            }
        }
        this.connections = List.copyOf(driver.connections(config, sink, this::connectionChanged));
        for (Link link : connections) {
            for (String channel : link.commandChannels()) {
                commandRoutes.put(channel, link);
            }
        }
    }

    /** Why a reading channel's device is unavailable now (its link being up), or null when it is available. */
    String unavailable(String channel) {
        return unavailable.get(channel);
    }

    String id() {
        return config.id();
    }

    ChannelDescriptor channel(String name) {
        return channels.get(name);
    }

    /** The producer of a reading channel, for wiring; null if there is none. */
    OutputPort reading(String channel) {
        return readings.get(channel);
    }

    /** The links of the driver's connections, in the driver's order. */
    List<Link> connections() {
        return connections;
    }

    /** The reading channels, the engine's {@code link} channel among them. */
    Set<String> readingChannels() {
        return readings.keySet();
    }

    /**
     * Has {@code changes} told of every change of the interface's state (up or down), under the link-state lock
     * and before the staleness it causes is in force, so a recording has it before any of its effects.
     */
    void onLinkChange(Consumer<Boolean> changes) {
        this.linkChanges = changes;
    }

    void watchdog(MotionWatchdog w) {
        this.watchdog = w;
    }

    boolean up() {
        return up;
    }

    void start() {
        sinceMicros = clock.nowMicros();
        for (Link c : connections) {
            c.start();
        }
        if (engineTellsLink) {
            linkTicker = clock.every(1_000_000, () -> states.locked(this::publishLink));
            states.locked(this::publishLink);
        }
    }

    void stop() {
        if (linkTicker != null) {
            try {
                linkTicker.close();
            } catch (Exception e) {
                LOG.debug("link ticker: {}", e.toString());
            }
        }
        for (Link c : connections) {
            c.stop();
        }
    }

    /** What became of a command: written to its connection, refused (counted), or on no connection at all. */
    enum Delivery { WRITTEN, REFUSED, UNROUTED }

    /** Sends a command sample from an actuator method to its channel. */
    Delivery command(String channel, Sample sample) {
        ChannelDescriptor d = channels.get(channel);
        Link link = commandRoutes.get(channel);
        if (d == null || link == null) {
            drop(channel, sample, "no connection carries it");
            return Delivery.UNROUTED;
        }
        if (!d.motion()) {
            return send(channel, sample, link);
        }
        // Under the motion lock: a trip either comes before the check (and the command is dropped) or after the
        // write (and its stop follows the command).
        synchronized (motionLock) {
            if (!motionAllowed()) {
                return refuse(channel, sample, "the motion watchdog has stopped the robot");
            }
            payOwedStop(link);
            return send(channel, sample, link);
        }
    }

    private boolean motionAllowed() {
        MotionWatchdog w = watchdog;
        return w == null || w.allowsMotion();
    }

    private Delivery send(String channel, Sample sample, Link link) {
        if (!link.command(channel, sample.payload())) {
            return refuse(channel, sample, "link " + config.id() + "/" + link.connectionName() + " is down");
        }
        commandsSent.increment();
        return Delivery.WRITTEN;
    }

    private Delivery refuse(String channel, Sample sample, String why) {
        drop(channel, sample, why);
        return Delivery.REFUSED;
    }

    /** Owes a stop on every connection that carries a motion channel (see the class comment). */
    void oweStop() {
        synchronized (motionLock) {
            for (Link link : connections) {
                if (carriesMotion(link)) {
                    stopsOwed.add(link);
                }
            }
        }
    }

    /** Pays the owed stops now, each connection from a thread of its own. */
    void stopMotion() {
        for (Link link : connections) {
            if (carriesMotion(link)) {
                Thread.ofVirtual().name("habla-stop-" + config.id()).start(() -> {
                    synchronized (motionLock) {
                        payOwedStop(link);
                    }
                });
            }
        }
    }

    /** Writes the stop owed on {@code link}, if any; it stays owed while the connection is down. */
    private void payOwedStop(Link link) {
        if (stopsOwed.contains(link) && link.stopMotion()) {
            stopsOwed.remove(link);
        }
    }

    private boolean carriesMotion(Link link) {
        return link.commandChannels().stream().map(channels::get).anyMatch(c -> c != null && c.motion());
    }

    /** Stops motion and waits briefly for the stop to be written (shutdown). */
    void stopMotionNow() {
        for (Link link : connections) {
            if (carriesMotion(link)) {
                synchronized (motionLock) {
                    if (link.stopMotion()) {
                        stopsOwed.remove(link);
                    }
                }
            }
        }
    }

    /**
     * Counts a dropped command and warns on the first and every 100th that mattered. A command to stand still on a
     * motion channel is dropped quietly (at DEBUG): the robot is stopped or its link is down, so nothing was lost.
     */
    private void drop(String channel, Sample sample, String why) {
        long n = commandsDropped.incrementAndGet();
        ChannelDescriptor d = channels.get(channel);
        if (d != null && d.motion() && standsStill(sample.payload())) {
            LOG.debug("interface {}: a stand-still command on {} dropped: {}", config.id(), channel, why);
            return;
        }
        long loud = droppedMoves.incrementAndGet();
        if (loud == 1 || loud % 100 == 0) {
            LOG.warn("interface {}: command on {} dropped ({} dropped so far): {}", config.id(), channel, n, why);
        }
    }

    /** Whether a motion command asks for no motion at all: every speed zero. */
    static boolean standsStill(Payload command) {
        if (command instanceof NumberValue n) {
            return n.value() == 0;
        }
        if (command instanceof VectorValue v) {
            for (double x : v.toArray()) {
                if (x != 0) {
                    return false;
                }
            }
            return true;
        }
        return false;
    }

    /**
     * Whether the interface is up: every connection it needs is (a driver's optional connections, such as a menu
     * server, do not count unless all of its connections are optional).
     */
    private boolean requiredUp() {
        List<Link> required = connections.stream().filter(c -> !c.optional()).toList();
        return (required.isEmpty() ? connections : required).stream().allMatch(Link::up);
    }

    /**
     * A connection went up or down: the interface is up when every connection it needs is. The staleness of what
     * depends on it changes first, then the link record goes out, so the record arrives with the stale flag of
     * the state it tells of.
     */
    private void connectionChanged() {
        states.locked(() -> {
            boolean all = requiredUp();
            if (all && !up) {
                // A fresh session tells its devices' availability again.
                unavailable.clear();
            }
            if (all != up) {
                up = all;
                sinceMicros = clock.nowMicros();
                linkChanges.accept(all);
                states.refreshStaleness();
                publishLink();
            } else if (connections.size() > 1) {
                // The interface stays up (or down), but the record says which connections are: tell it now.
                publishLink();
            }
        });
    }

    /** Publishes the link record; under the link-state lock, so it never overtakes a change. */
    private void publishLink() {
        if (!engineTellsLink) {
            return;
        }
        StringBuilder detail = new StringBuilder();
        ObjectNode each = JsonNodeFactory.instance.objectNode();
        for (Link c : connections) {
            each.put(c.connectionName(), c.up());
            if (!c.up()) {
                detail.append(detail.length() == 0 ? "" : "; ").append(c.connectionName())
                        .append(c.optional() ? " (optional)" : "").append(" down")
                        .append(c.lastError().isEmpty() ? "" : ": " + c.lastError());
            }
        }
        RecordValue value = RecordValue.builder().put("up", up).put("interface", config.id())
                .put("detail", detail.length() == 0 ? "all connections up" : detail.toString())
                .set("connections", each).build();
        readings.get(Driver.LINK_CHANNEL.name()).publish(value, clock.nowMicros(), false);
    }

    ObjectNode status() {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("id", config.id());
        n.put("driver", config.driver());
        n.put("address", config.address().toString());
        n.put("up", up);
        n.put("sinceMicros", sinceMicros);
        n.set("robot", robotInfo);
        ArrayNode conns = n.putArray("connections");
        connections.forEach(c -> conns.add(c.status()));
        n.put("malformed", malformed.sum());
        n.put("unknownChannel", unknownChannel.sum());
        n.put("commandsSent", commandsSent.sum());
        n.put("commandsDropped", commandsDropped.get());
        if (!unavailable.isEmpty()) {
            ObjectNode un = n.putObject("unavailable");
            unavailable.forEach(un::put);
        }
        ObjectNode rs = n.putObject("readings");
        readings.forEach((name, port) -> rs.put(name, port.published()));
        return n;
    }

    /** Turns what the sessions decode into samples on the reading channels. */
    private final class Sink implements ReadingSink {
        @Override
        public void reading(String channel, Payload value) {
            reading(channel, value, clock.nowMicros());
        }

        @Override
        public void reading(String channel, Payload value, long sourceMicros) {
            OutputPort port = readings.get(channel);
            ChannelDescriptor d = channels.get(channel);
            if (port == null || (engineTellsLink && Driver.LINK_CHANNEL.name().equals(channel))) {
                unknownChannel.increment();
                LOG.debug("interface {}: reading on unknown channel '{}' ignored", config.id(), channel);
                return;
            }
            if (!d.kind().accepts(value.kind())) {
                malformed("reading on " + channel + " is " + value.kind().wireName() + ", expected "
                        + d.kind().wireName());
                return;
            }
            port.publish(value, sourceMicros, false);
        }

        @Override
        public void malformed(String what) {
            malformed.increment();
            long n = malformed.sum();
            if (n <= 10 || n % 1000 == 0) {
                LOG.warn("interface {}: malformed input dropped ({} so far): {}", config.id(), n, what);
            }
        }

        @Override
        public void availability(String channel, boolean available, String why) {
            if (!readings.containsKey(channel) || Driver.LINK_CHANNEL.name().equals(channel)) {
                unknownChannel.increment();
                return;
            }
            // The device's state and the staleness it causes change as one step, like a link's.
            states.locked(() -> {
                String before = available ? unavailable.remove(channel) : unavailable.put(channel, why);
                if ((before == null) != available) {
                    LOG.info("interface {}: the device of channel {} is {} ({})", config.id(), channel,
                            available ? "available again" : "unavailable", why);
                    states.refreshStaleness();
                }
            });
        }

        @Override
        public void robotInfo(ObjectNode info) {
            ObjectNode merged = robotInfo.deepCopy();
            merged.setAll(info.deepCopy());
            robotInfo = merged;
            LOG.info("interface {}: robot {}", config.id(), merged);
        }
    }
}
