package org.habla.graph;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import org.habla.driver.ChannelDescriptor;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.Sample;
import org.habla.sample.VectorValue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Where one interface's commands go: each to the connection that carries its channel, written at once or dropped
 * and counted — never delayed — while that connection is down or the motion watchdog has tripped.
 *
 * <p>A watchdog trip leaves a stop <em>owed</em> on every connection that carries a motion channel. It is
 * paid at once from a thread of its own and, at the latest, just before the next motion command on that
 * connection, under one lock: a new motion never reaches the robot ahead of the stop, and a stop that could
 * not be written while the connection was down is written before the first motion after it comes back.
 */
final class InterfaceCommands {

    private static final Logger LOG = LoggerFactory.getLogger(InterfaceCommands.class);

    private final String interfaceId;
    private final Map<String, ChannelDescriptor> channels;
    private final List<Link> connections;
    private final Map<String, Link> routes = new HashMap<>();
    private final LongAdder commandsSent = new LongAdder();
    private final AtomicLong commandsDropped = new AtomicLong();
    private final AtomicLong droppedMoves = new AtomicLong();
    private final Object motionLock = new Object();
    private final Set<Link> stopsOwed = new HashSet<>();
    private volatile MotionWatchdog watchdog;
    private volatile Drop lastDrop;

    InterfaceCommands(String interfaceId, Map<String, ChannelDescriptor> channels, List<Link> connections) {
        this.interfaceId = interfaceId;
        this.channels = channels;
        this.connections = connections;
        for (Link link : connections) {
            for (String channel : link.commandChannels()) {
                routes.put(channel, link);
            }
        }
    }

    void watchdog(MotionWatchdog w) {
        this.watchdog = w;
    }

    /** Adds how many commands were written and dropped, and why the last was dropped, to an interface's status. */
    void countsTo(ObjectNode status) {
        status.put("commandsSent", commandsSent.sum());
        status.put("commandsDropped", commandsDropped.get());
        Drop last = lastDrop;
        if (last != null) {
            status.putObject("lastDrop").put("channel", last.channel()).put("why", last.why());
        }
    }

    /** The last command dropped: its channel and why. */
    private record Drop(String channel, String why) {
    }

    /** What became of a command: written to its connection, refused (counted), or on no connection at all. */
    enum Delivery { WRITTEN, REFUSED, UNROUTED }

    /** Sends a command sample from an actuator method to its channel. */
    Delivery command(String channel, Sample sample) {
        ChannelDescriptor d = channels.get(channel);
        Link link = routes.get(channel);
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
        CommandResult result = link.command(channel, sample.payload());
        if (!result.written()) {
            return refuse(channel, sample, result.refusal() != null ? result.refusal()
                    : "link " + interfaceId + "/" + link.connectionName() + " is down");
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
                Thread.ofVirtual().name("habla-stop-" + interfaceId).start(() -> {
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
        lastDrop = new Drop(channel, why);
        ChannelDescriptor d = channels.get(channel);
        if (d != null && d.motion() && standsStill(sample.payload())) {
            LOG.debug("interface {}: a stand-still command on {} dropped: {}", interfaceId, channel, why);
            return;
        }
        long loud = droppedMoves.incrementAndGet();
        if (loud == 1 || loud % 100 == 0) {
            LOG.warn("interface {}: command on {} dropped ({} dropped so far): {}", interfaceId, channel, n, why);
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
}
