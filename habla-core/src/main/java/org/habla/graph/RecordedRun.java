package org.habla.graph;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.habla.config.InterfaceConfig;
import org.habla.driver.ChannelDescriptor;

/**
 * A graph run on a recording: every interface on a {@link RecordedDriver} with the recorded channels, every input
 * behind a {@link ReplayedInput} that skips what the recorded run skipped, its work counted so that the replay can
 * feed the next event once the graph is idle ({@link GraphReplay}).
 */
final class RecordedRun implements GraphRun {

    private final Map<String, List<ChannelDescriptor>> channels;
    private final RecordedSkips skips;
    private final Map<String, RecordedDriver> drivers = new HashMap<>();
    private final WorkCount work = new WorkCount();
    private GraphReplay replay;

    /** @param channels the recorded channels of each interface, by interface id */
    RecordedRun(Map<String, List<ChannelDescriptor>> channels, RecordedSkips skips) {
        this.channels = channels;
        this.skips = skips;
    }

    @Override
    public InterfaceDriver driver(InterfaceConfig config) {
        RecordedDriver d = new RecordedDriver(channels.getOrDefault(config.id(), List.of()));
        drivers.put(config.id(), d);
        return d;
    }

    @Override
    public WorkCount work() {
        return work;
    }

    @Override
    public InputEntry entry(String methodId, InputSlot slot) {
        return new ReplayedInput(methodId, slot, skips);
    }

    @Override
    public void wired(Map<String, MethodRunner> runners, List<ExposedMethod> exposed, GraphTopology topology,
            MotionWatchdog watchdog) {
        replay = new GraphReplay(Map.copyOf(drivers), runners, exposed, topology, watchdog, work);
    }

    @Override
    public GraphReplay replay() {
        if (replay == null) {
            throw new IllegalStateException("the graph is not wired yet");
        }
        return replay;
    }
}
