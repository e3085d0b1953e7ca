package org.habla.graph;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.habla.config.ChannelRef;
import org.habla.config.HablaConfig;
import org.habla.config.MethodConfig;
import org.habla.config.Source;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.Input;
import org.habla.method.Output;

/**
 * Connects the parts of a graph as its config says, once, while the graph is built: every input to the output,
 * interface channel or control socket that feeds it, every command output to its interface channel (through the
 * recording's {@link InterfaceTap}), every exposed method to its socket, the notices a method tells control
 * clients to the sockets whose values reach it, and the motion resets of the methods that lead to a motion channel.
 */
final class GraphWiring {

    private final HablaConfig config;
    private final GraphTopology topology;
    private final Map<String, MethodRunner> runners;
    private final Map<String, InterfaceLink> links;
    private final MotionWatchdog watchdog;
    private final GraphTap tap;
    private final Entries entries;
    private final WiredShapes shapes;
    private final List<ExposedMethod> exposed = new ArrayList<>();

    /** What the wires of one method's input hand samples to ({@link GraphRun#entry}). */
    @FunctionalInterface
    interface Entries {
        InputEntry of(String methodId, InputSlot slot);
    }

    private GraphWiring(HablaConfig config, GraphTopology topology, Map<String, MethodRunner> runners,
            Map<String, InterfaceLink> links, MotionWatchdog watchdog, GraphTap tap, Entries entries,
            WiredShapes shapes) {
        this.config = config;
        this.topology = topology;
        this.runners = runners;
        this.links = links;
        this.watchdog = watchdog;
        this.tap = tap;
        this.entries = entries;
        this.shapes = shapes;
    }

    /**
     * Wires the graph's methods and interfaces, every input's wires and control writes to what {@code entries} gives
     * for its slot, telling {@code shapes} what feeds each input; returns the exposed methods, in config order.
     */
    static List<ExposedMethod> wire(HablaConfig config, GraphTopology topology, Map<String, MethodRunner> runners,
            Map<String, InterfaceLink> links, MotionWatchdog watchdog, GraphTap tap, Entries entries,
            WiredShapes shapes) {
        GraphWiring w = new GraphWiring(config, topology, runners, links, watchdog, tap, entries, shapes);
        for (MethodConfig mc : config.methods()) {
            w.wire(mc);
        }
        w.routeNotices();
        for (String id : w.motionPath()) {
            runners.get(id).followMotionResets(watchdog::resets);
        }
        return List.copyOf(w.exposed);
    }

    private void wire(MethodConfig mc) {
        MethodRunner runner = runners.get(mc.id());
        Map<Input<?>, InputEntry> controlled = new HashMap<>();
        for (Map.Entry<String, Source> e : mc.inputs().entrySet()) {
            Input<?> input = runner.method().input(e.getKey()).orElseThrow();
            InputEntry entry = entries.of(mc.id(), runner.slot(input));
            switch (e.getValue()) {
                case Source.MethodOutput mo -> {
                    MethodRunner from = runners.get(mo.methodId());
                    Output<?> out = from.method().output(mo.output()).orElseThrow();
                    feed(from.port(out), runner, entry);
                    shapes.fromOutput(mc.id(), input, from.id(), out);
                }
                case Source.Channel ch -> {
                    InterfaceLink link = links.get(ch.interfaceId());
                    feed(link.reading(ch.channel()), runner, entry);
                    runner.bindChannel(input, link.channel(ch.channel()));
                    shapes.fromChannel(mc.id(), input, link.channel(ch.channel()));
                }
                case Source.Control c -> controlled.put(input, entry);
            }
        }
        for (Map.Entry<String, ChannelRef> e : mc.commands().entrySet()) {
            Output<?> out = runner.method().output(e.getKey()).orElseThrow();
            InterfaceLink link = links.get(e.getValue().interfaceId());
            String channel = e.getValue().channel();
            ChannelDescriptor descriptor = link.channel(channel);
            if (descriptor != null) {
                runner.bindCommandChannel(out, descriptor);
            }
            runner.port(out).subscribe(InterfaceTap.commands(link, channel, tap));
        }
        mc.expose().ifPresent(x -> exposed.add(new ExposedMethod(runner, x, controlled, watchdog, tap,
                topology.actuates(mc.id()), out -> shapes.of(mc.id(), out))));
    }

    /**
     * Wires {@code producer} to an input of {@code runner}: a method that runs on the producer's thread gets each
     * sample before the methods whose threads are woken, so the light chain runs first.
     */
    private static void feed(Producer producer, MethodRunner runner, InputEntry entry) {
        if (runner.inline()) {
            producer.subscribeAhead(entry::offer);
        } else {
            producer.subscribe(entry::offer);
        }
    }

    /** Sends what each method tells control clients to the sockets whose values reach it. */
    private void routeNotices() {
        for (MethodRunner r : runners.values()) {
            List<ExposedMethod> told = exposed.stream().filter(x -> !x.controlInputs().isEmpty()
                    && topology.downstream(x.methodId()).contains(r.id())).toList();
            if (!told.isEmpty()) {
                r.tellControlVia(notice -> told.forEach(x -> x.notice(notice)));
            }
        }
    }

    /**
     * The methods whose outputs lead, through other methods or directly, to a motion command channel: the ones
     * that must forget their motion when the watchdog stops the robot.
     */
    private Set<String> motionPath() {
        Set<String> found = new LinkedHashSet<>();
        for (MethodConfig mc : config.methods()) {
            boolean drives = mc.commands().values().stream().anyMatch(ref -> {
                ChannelDescriptor d = links.get(ref.interfaceId()).channel(ref.channel());
                return d != null && d.motion();
            });
            if (drives) {
                topology.feeding(mc.id(), found);
            }
        }
        return found;
    }
}
