package org.habla.graph;

import java.util.List;
import java.util.Map;
import org.habla.config.InterfaceConfig;
import org.habla.plugin.PluginRegistry;

/** A graph run live: its interfaces on the robots' plugin drivers, its wires straight into the input slots. */
final class LiveRun implements GraphRun {

    private final PluginRegistry registry;

    LiveRun(PluginRegistry registry) {
        this.registry = registry;
    }

    @Override
    public InterfaceDriver driver(InterfaceConfig config) {
        return LiveDriver.create(registry, config);
    }

    @Override
    public WorkCount work() {
        return WorkCount.NONE;
    }

    @Override
    public InputEntry entry(String methodId, InputSlot slot) {
        return slot;
    }

    @Override
    public void wired(Map<String, MethodRunner> runners, List<ExposedMethod> exposed, GraphTopology topology,
            MotionWatchdog watchdog) {
    }

    @Override
    public GraphReplay replay() {
        throw new IllegalStateException("this graph runs live interfaces, not a recording");
    }
}
