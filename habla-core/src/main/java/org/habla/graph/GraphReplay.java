package org.habla.graph;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.habla.sample.Payload;

/**
 * What a replay drives in a graph built from a recording ({@link MethodGraph#replaying}): recorded readings, link
 * changes and periodic work go in here, and the replay asks where an event can reach and whether the graph is idle.
 * A live graph has none ({@link MethodGraph#replay} refuses).
 */
public final class GraphReplay {

    static final String WATCHDOG_TASK = "watchdog";

    private final Map<String, RecordedDriver> drivers;
    private final Map<String, MethodRunner> runners;
    private final Map<String, Set<String>> upstreamInterfaces = new HashMap<>();
    private final List<ExposedMethod> exposed;
    private final GraphTopology topology;
    private final MotionWatchdog watchdog;
    private final WorkCount work;

    GraphReplay(Map<String, RecordedDriver> drivers, Map<String, MethodRunner> runners, List<ExposedMethod> exposed,
            GraphTopology topology, MotionWatchdog watchdog, WorkCount work) {
        this.drivers = drivers;
        this.runners = runners;
        for (String id : runners.keySet()) {
            upstreamInterfaces.put(id, topology.upstreamInterfaces(id));
        }
        this.exposed = exposed;
        this.topology = topology;
        this.watchdog = watchdog;
        this.work = work;
    }

    /** Feeds a recorded reading to an interface, through its driver as the robot's session delivered it. */
    public void reading(String interfaceId, String channel, Payload value, long sourceMicros) {
        driver(interfaceId).reading(channel, value, sourceMicros);
    }

    /** Sets the state of an interface link, as recorded, through its driver's connection. */
    public void link(String interfaceId, boolean up) {
        driver(interfaceId).link(up);
    }

    /** Runs recorded periodic work ({@link GraphTap#periodic}'s task names); false for a task this graph lacks. */
    public boolean periodic(String task) {
        if (task.equals(WATCHDOG_TASK)) {
            watchdog.check();
            return true;
        }
        if (task.startsWith(MethodRunner.TICK_PREFIX)) {
            MethodRunner r = runners.get(task.substring(MethodRunner.TICK_PREFIX.length()));
            if (r != null) {
                r.requestTick();
                return true;
            }
        }
        return false;
    }

    /**
     * The input samples a method's state reflects so far (see {@link GraphTap#periodic}); the replay places
     * recorded ticks by it. -1 for a method the graph does not have.
     */
    public long handled(String methodId) {
        MethodRunner r = runners.get(methodId);
        return r == null ? -1 : r.consumed();
    }

    /** Whether readings of an interface can reach a method (the interface is upstream of it). */
    public boolean reaches(String interfaceId, String methodId) {
        return upstreamInterfaces.getOrDefault(methodId, Set.of()).contains(interfaceId);
    }

    /** Whether what a control client writes to socket {@code socket} can reach a method. */
    public boolean reachesFromControl(String socket, String methodId) {
        for (ExposedMethod x : exposed) {
            if (x.name().equals(socket)) {
                return topology.downstream(x.methodId()).contains(methodId);
            }
        }
        return false;
    }

    /**
     * Waits until every effect of what came in has been handled — no sample waiting or being handled, no turn
     * or background task under way; false if that took longer than {@code millis}.
     */
    public boolean awaitIdle(long millis) throws InterruptedException {
        return work.awaitIdle(millis);
    }

    private RecordedDriver driver(String interfaceId) {
        RecordedDriver driver = drivers.get(interfaceId);
        if (driver == null) {
            throw new IllegalArgumentException("no interface '" + interfaceId + "' in the config");
        }
        return driver;
    }
}
