package org.habla.graph;

import java.util.List;
import java.util.Map;
import org.habla.config.InterfaceConfig;

/**
 * What differs between a graph that runs live and one that replays a recording, in one place: what its interfaces
 * run on, whether it counts its work, what its inputs' wires hand samples to, and what a replay can drive. The
 * rest of the engine — runners, slots, wiring, staleness — is built the same way either way and is never told
 * which it is.
 *
 * <pre>
 *                    interfaces on       work counted   an input's wires go to     replay()
 *   LiveRun          plugin drivers      no             its InputSlot              refused
 *   RecordedRun      RecordedDriver      yes            a ReplayedInput → slot     the GraphReplay
 * </pre>
 */
sealed interface GraphRun permits LiveRun, RecordedRun {

    /** What the interface of {@code config} runs on. */
    InterfaceDriver driver(InterfaceConfig config);

    /** How the graph counts the work it holds ({@link WorkCount#NONE} when nothing waits on it). */
    WorkCount work();

    /** What the wires and control writes of {@code methodId}'s input hand samples to. */
    InputEntry entry(String methodId, InputSlot slot);

    /** The graph is built and wired; nothing runs yet. */
    void wired(Map<String, MethodRunner> runners, List<ExposedMethod> exposed, GraphTopology topology,
            MotionWatchdog watchdog);

    /**
     * What a replay drives in the graph.
     *
     * @throws IllegalStateException if the graph runs live interfaces, not a recording
     */
    GraphReplay replay();
}
