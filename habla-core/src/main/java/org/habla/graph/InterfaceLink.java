package org.habla.graph;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import org.habla.config.InterfaceConfig;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Driver;
import org.habla.driver.LinkReport;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One robot interface in the running graph: the connections its {@link InterfaceDriver} keeps, whether the
 * interface is up, and the {@code link} record that tells it. What comes in is its {@link InterfaceReadings} (a
 * producer per reading channel); what goes out, its {@link InterfaceCommands} (routing, motion stops, drops).
 *
 * <p>What the interface runs on — a robot's driver or a recording — is taken the same way. A recording sees the
 * interface at its edges ({@link InterfaceTap}): its reading channels' ports, what {@link #command} says became of
 * a command, and the changes {@link #onLinkChange} tells.
 */
final class InterfaceLink {

    private static final Logger LOG = LoggerFactory.getLogger(InterfaceLink.class);

    private final InterfaceConfig config;
    private final EngineClock clock;
    private final Map<String, ChannelDescriptor> channels = new HashMap<>();
    private final List<Link> connections;
    private final LinkStates states;
    /** Whether the engine tells the {@code link} record, or the driver's connections deliver it (a recording). */
    private final boolean engineTellsLink;
    private final InterfaceReadings readings;
    private final InterfaceCommands commands;
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
        this.readings = new InterfaceReadings(config.id(), channels, engineTellsLink, clock, states);
        this.connections = List.copyOf(driver.connections(config, readings.sink(), this::connectionChanged));
        this.commands = new InterfaceCommands(config.id(), channels, connections);
    }

    /** Why a reading channel's device is unavailable now (its link being up), or null when it is available. */
    String unavailable(String channel) {
        return readings.unavailable(channel);
    }

    String id() {
        return config.id();
    }

    ChannelDescriptor channel(String name) {
        return channels.get(name);
    }

    /** The producer of a reading channel, for wiring; null if there is none. */
    Producer reading(String channel) {
        return readings.port(channel);
    }

    /** The reading channels, the engine's {@code link} channel among them. */
    Set<String> readingChannels() {
        return readings.channels();
    }

    /** The links of the driver's connections, in the driver's order. */
    List<Link> connections() {
        return connections;
    }

    /**
     * Has {@code changes} told of every change of the interface's state (up or down), under the link-state lock
     * and before the staleness it causes is in force, so a recording has it before any of its effects.
     */
    void onLinkChange(Consumer<Boolean> changes) {
        this.linkChanges = changes;
    }

    void watchdog(MotionWatchdog w) {
        commands.watchdog(w);
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

    /** Sends a command sample from an actuator method to its channel, or drops it (see {@link InterfaceCommands}). */
    InterfaceCommands.Delivery command(String channel, Sample sample) {
        return commands.command(channel, sample);
    }

    /** Owes a stop on every connection that carries a motion channel (a watchdog trip, before anything sees it). */
    void oweStop() {
        commands.oweStop();
    }

    /** Pays the owed stops now, each connection from a thread of its own. */
    void stopMotion() {
        commands.stopMotion();
    }

    /** Stops motion and waits briefly for the stop to be written (shutdown). */
    void stopMotionNow() {
        commands.stopMotionNow();
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
                readings.forgetAvailability();
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

    /** Publishes the link record, if the engine tells it; under the link-state lock, so it never overtakes a change. */
    private void publishLink() {
        if (!engineTellsLink) {
            return;
        }
        StringBuilder detail = new StringBuilder();
        Map<String, Boolean> each = new LinkedHashMap<>();
        for (Link c : connections) {
            each.put(c.connectionName(), c.up());
            if (!c.up()) {
                detail.append(detail.length() == 0 ? "" : "; ").append(c.connectionName())
                        .append(c.optional() ? " (optional)" : "").append(" down")
                        .append(c.lastError().isEmpty() ? "" : ": " + c.lastError());
            }
        }
        RecordValue value = RecordValue.of(new LinkReport(up, config.id(),
                detail.length() == 0 ? "all connections up" : detail.toString(), each));
        readings.port(Driver.LINK_CHANNEL.name()).publish(value, clock.nowMicros(), false);
    }

    ObjectNode status() {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("id", config.id());
        n.put("driver", config.driver());
        n.put("address", config.address().toString());
        n.put("up", up);
        n.put("sinceMicros", sinceMicros);
        n.set("robot", readings.robotInfo());
        ArrayNode conns = n.putArray("connections");
        connections.forEach(c -> conns.add(c.status()));
        readings.countsTo(n);
        commands.countsTo(n);
        readings.publishedTo(n);
        return n;
    }
}
