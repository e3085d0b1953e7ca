package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Stops the robot when its control architecture goes quiet or away. Armed by the first value a
 * control client writes to an actuating socket; trips when no value has come for the timeout, or at once
 * when the client commanding such a socket disconnects or releases control. A trip sends every link's stop and then drops motion commands
 * until a control client writes again, so nothing queued before the trip moves the robot later.
 */
final class MotionWatchdog {

    private static final Logger LOG = LoggerFactory.getLogger(MotionWatchdog.class);

    private final long timeoutMicros;
    private final EngineClock clock;
    private final List<InterfaceLink> links;
    private final AtomicLong trips = new AtomicLong();
    private final AtomicLong resets = new AtomicLong();
    private volatile long lastWriteMicros;
    private volatile boolean armed;
    private volatile boolean tripped;
    private volatile String lastReason = "";

    MotionWatchdog(long timeoutMillis, EngineClock clock, List<InterfaceLink> links) {
        this.timeoutMicros = timeoutMillis * 1_000;
        this.clock = clock;
        this.links = links;
    }

    /** A control client wrote a value: motion is allowed again and the silence timer restarts. */
    synchronized void controlWrite() {
        lastWriteMicros = clock.nowMicros();
        armed = true;
        if (tripped) {
            resets.incrementAndGet();
            tripped = false;
            LOG.info("motion watchdog: control is back, motion commands flow again");
        }
    }

    /** Called periodically by the engine. */
    synchronized void check() {
        if (armed && timeoutMicros > 0 && clock.nowMicros() - lastWriteMicros > timeoutMicros) {
            trip("no control value for " + timeoutMicros / 1_000 + " ms");
        }
    }

    /** The client commanding an actuating socket disconnected or gave control back. */
    synchronized void writerLeft() {
        if (armed) {
            trip("the control client commanding the robot left or released control");
        }
    }

    /** Stops every motion now (also used at shutdown). */
    synchronized void trip(String reason) {
        armed = false;
        for (InterfaceLink link : links) {
            link.oweStop(); // before anything can see the trip: no motion may pass ahead of the stop
        }
        tripped = true;
        resets.incrementAndGet();
        lastReason = reason;
        trips.incrementAndGet();
        LOG.warn("motion watchdog: stopping the robot: {}", reason);
        for (InterfaceLink link : links) {
            link.stopMotion();
        }
    }

    /** Motion resets so far: trips, and returns of control after one. */
    long resets() {
        return resets.get();
    }

    boolean allowsMotion() {
        return !tripped;
    }

    long timeoutMillis() {
        return timeoutMicros / 1_000;
    }

    /** The watchdog's part of the graph's status: its timeout, whether it has tripped, how often and why last. */
    ObjectNode status() {
        ObjectNode w = JsonNodeFactory.instance.objectNode();
        w.put("timeoutMs", timeoutMillis());
        w.put("tripped", tripped);
        w.put("trips", trips.get());
        String why = lastReason;
        if (!why.isEmpty()) {
            w.put("lastReason", why);
        }
        return w;
    }
}
