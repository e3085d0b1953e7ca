package org.habla.config;

import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.OutputPort;
import org.habla.sample.PayloadKind;

/**
 * Checks the graph the config wires: every reference resolves, payload kinds fit, channels are used in
 * the right direction and from the right layer, and every wire between methods obeys the layer rule (a
 * method exchanges data only with its own layer or a neighbouring one). Entries that could not be read
 * are skipped; their errors are already recorded.
 */
final class WiringCheck {

    static final String LAYER_RULE = "the layer rule: a method exchanges data only with methods of its own"
            + " layer or a neighbouring layer (sensors_actuators - processing - virtual)";

    private final ConfigErrors errors;
    private final Map<String, MethodEntry> methods = new LinkedHashMap<>();
    private final Map<String, InterfaceEntry> interfaces = new LinkedHashMap<>();

    WiringCheck(ConfigErrors errors, List<InterfaceEntry> interfaceEntries, List<MethodEntry> methodEntries) {
        this.errors = errors;
        interfaceEntries.stream().filter(i -> i.id() != null).forEach(i -> interfaces.putIfAbsent(i.id(), i));
        methodEntries.stream().filter(m -> m.id() != null).forEach(m -> methods.putIfAbsent(m.id(), m));
    }

    void run(List<MethodEntry> entries) {
        for (MethodEntry m : entries) {
            m.inputs().forEach((name, source) -> input(m, name, source));
            m.commands().forEach((name, target) -> command(m, name, target));
            requiredInputs(m);
            expose(m);
        }
        cycles(entries);
    }

    /**
     * Every wiring cycle must be declared: a {@code feedback} input names a wire that lies on a cycle, and the
     * wires left when the declared ones are taken out must close none. Each undeclared cycle is reported once,
     * at the input whose wire closes it.
     */
    private void cycles(List<MethodEntry> entries) {
        Map<String, Map<String, Source>> inputs = new LinkedHashMap<>();
        entries.stream().filter(m -> m.id() != null).forEach(m -> inputs.putIfAbsent(m.id(), m.inputs()));
        WiringCycles cycles = WiringCycles.of(inputs);
        Set<WiringCycles.Wire> declared = new HashSet<>();
        for (MethodEntry m : entries) {
            if (m.id() == null || methods.get(m.id()) != m) {
                continue;
            }
            m.feedback().forEach((input, at) -> {
                Source source = m.inputs().get(input);
                if (source == null) {
                    if (!m.inputKeys().contains(input)) {
                        errors.add(at, "'" + input + "' is not a wired input of '" + m.id() + "' (wired: "
                                + names(m.inputKeys()) + ")");
                    }
                    return;
                }
                Optional<WiringCycles.Wire> wire = cycles.wireInto(m.id(), input);
                if (wire.isEmpty()) {
                    if (!(source instanceof Source.MethodOutput)) {
                        errors.add(at, "'" + input + "' reads '" + source.text()
                                + "': only a wire from a method's output can close a cycle");
                    }
                } else if (!cycles.onCycle(wire.get())) {
                    errors.add(at, "'" + input + "' ('" + source.text() + "') is on no wiring cycle: nothing to declare");
                } else {
                    declared.add(wire.get());
                }
            });
        }
        for (int i = 0; i <= inputs.size(); i++) {
            Optional<List<WiringCycles.Wire>> cycle = cycles.undeclaredCycle(declared::contains);
            if (cycle.isEmpty()) {
                return;
            }
            WiringCycles.Wire closing = cycle.get().get(cycle.get().size() - 1);
            MethodEntry m = methods.get(closing.toMethod());
            errors.add(m.path().field("inputs").field(closing.input()), "'" + closing.fromMethod() + "."
                    + closing.output() + "' closes a wiring cycle (" + route(cycle.get()) + "): a sample could go round"
                    + " it for ever. Rewire it, or declare it with \"feedback\": [\"" + closing.input()
                    + "\"] on method '" + m.id() + "' (a declared cycle runs on latest inputs only)");
            declared.add(closing);
        }
    }

    private static String route(List<WiringCycles.Wire> cycle) {
        StringBuilder b = new StringBuilder(cycle.get(0).fromMethod());
        cycle.forEach(w -> b.append(" -> ").append(w.toMethod()));
        return b.toString();
    }

    private void input(MethodEntry m, String name, Source source) {
        JsonPath path = m.path().field("inputs").field(name);
        InputPort<?> in = null;
        if (m.ports() != null) {
            in = m.ports().input(name).orElse(null);
            if (in == null) {
                errors.add(path, "'" + name + "' is not an input of type '" + m.type() + "' (inputs: "
                        + names(m.ports().inputs().stream().map(InputPort::name).toList()) + ")");
            }
        }
        PayloadKind wants = in == null ? PayloadKind.ANY : in.kind();
        switch (source) {
            case Source.MethodOutput(String methodId, String outputName) -> {
                MethodEntry from = methods.get(methodId);
                if (from == null) {
                    errors.add(path, "unknown method '" + methodId + "' (methods: " + names(methods.keySet()) + ")");
                    return;
                }
                if (m.layer() != null && from.layer() != null && !from.layer().neighbours(m.layer())) {
                    errors.add(path, "'" + source.text() + "' breaks " + LAYER_RULE + "; '" + methodId + "' is in the "
                            + from.layer().configName() + " layer and '" + m.id() + "' in the "
                            + m.layer().configName() + " layer");
                }
                if (from.ports() == null) {
                    return;
                }
                Optional<OutputPort<?>> out = from.ports().output(outputName);
                if (out.isEmpty()) {
                    errors.add(path, "method '" + methodId + "' (type '" + from.type() + "') has no output '"
                            + outputName + "' (outputs: " + names(from.ports().outputs().stream().map(OutputPort::name).toList()) + ")");
                } else if (!wants.accepts(out.get().kind())) {
                    errors.add(path, kindMismatch(source.text(), out.get().kind(), name, wants));
                }
            }
            case Source.Channel(String interfaceId, String channel) -> {
                if (m.layer() != null && m.layer() != Layer.SENSORS_ACTUATORS) {
                    errors.add(path, "'" + source.text() + "': only a sensors_actuators method reads interface "
                            + "channels; '" + m.id() + "' is in the " + m.layer().configName() + " layer");
                }
                channel(path, interfaceId, channel).ifPresent(c -> {
                    if (c.direction() == ChannelDescriptor.Direction.COMMAND) {
                        errors.add(path, "'" + source.text() + "' is a command channel; an input reads a reading channel");
                    } else if (!wants.accepts(c.kind())) {
                        errors.add(path, kindMismatch(source.text(), c.kind(), name, wants));
                    }
                });
            }
            case Source.Control() -> {
                if (m.layer() != null && m.layer() != Layer.VIRTUAL) {
                    errors.add(path, "'control': only a virtual method takes values from control clients; '"
                            + m.id() + "' is in the " + m.layer().configName() + " layer");
                } else if (!m.exposeGiven()) {
                    errors.add(path, "'control' needs a control socket: give the method an 'expose'");
                }
            }
        }
    }

    private void command(MethodEntry m, String outputName, ChannelRef target) {
        JsonPath path = m.path().field("commands").field(outputName);
        if (m.layer() != null && m.layer() != Layer.SENSORS_ACTUATORS) {
            errors.add(path, "only a sensors_actuators method writes interface commands; '" + m.id()
                    + "' is in the " + m.layer().configName() + " layer");
        }
        OutputPort<?> out = null;
        if (m.ports() != null) {
            out = m.ports().output(outputName).orElse(null);
            if (out == null) {
                errors.add(path, "'" + outputName + "' is not an output of type '" + m.type() + "' (outputs: "
                        + names(m.ports().outputs().stream().map(OutputPort::name).toList()) + ")");
            }
        }
        OutputPort<?> output = out;
        channel(path, target.interfaceId(), target.channel()).ifPresent(c -> {
            if (c.direction() == ChannelDescriptor.Direction.READING) {
                errors.add(path, "'" + target.text() + "' is a reading channel; commands write a command channel");
            } else if (output != null && !c.kind().accepts(output.kind())) {
                errors.add(path, "kind mismatch: output '" + outputName + "' gives " + output.kind().wireName()
                        + " but '" + target.text() + "' takes " + c.kind().wireName());
            }
        });
    }

    private Optional<ChannelDescriptor> channel(JsonPath path, String interfaceId, String channel) {
        InterfaceEntry iface = interfaces.get(interfaceId);
        if (iface == null) {
            errors.add(path, "unknown interface '" + interfaceId + "' (interfaces: " + names(interfaces.keySet()) + ")");
            return Optional.empty();
        }
        if (iface.made() == null) {
            return Optional.empty();
        }
        Optional<ChannelDescriptor> c = iface.channel(channel);
        if (c.isEmpty()) {
            errors.add(path, "interface '" + interfaceId + "' (driver '" + iface.driver() + "') has no channel '"
                    + channel + "' (channels: " + names(iface.channels().stream().map(ChannelDescriptor::name).toList()) + ")");
        }
        return c;
    }

    private void requiredInputs(MethodEntry m) {
        if (m.ports() == null) {
            return;
        }
        for (InputPort<?> in : m.ports().inputs()) {
            if (!in.optional() && !m.inputKeys().contains(in.name())) {
                errors.add(m.path().field("inputs"), "required input '" + in.name() + "' (" + in.kind().wireName()
                        + ") of type '" + m.type() + "' is not wired");
            }
        }
    }

    private void expose(MethodEntry m) {
        if (m.expose().isEmpty()) {
            return;
        }
        JsonPath path = m.path().field("expose");
        if (m.layer() != null && m.layer() != Layer.VIRTUAL) {
            errors.add(path, "only a virtual method has a control socket; '" + m.id() + "' is in the "
                    + m.layer().configName() + " layer");
        }
        boolean takesControl = m.inputs().values().stream().anyMatch(s -> s instanceof Source.Control);
        if (m.ports() != null && m.ports().outputs().isEmpty() && !takesControl) {
            errors.add(path, "an exposed method needs an output or a 'control' input, and '" + m.id() + "' has neither");
        }
    }

    private static String kindMismatch(String source, PayloadKind gives, String input, PayloadKind takes) {
        return "kind mismatch: '" + source + "' gives " + gives.wireName() + " but input '" + input + "' takes "
                + takes.wireName();
    }

    private static String names(java.util.Collection<String> names) {
        return names.isEmpty() ? "none" : names.stream().sorted().collect(Collectors.joining(", "));
    }
}
