package org.habla.method;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * The inputs and outputs of a method type, known without making a method: a provider lists them
 * ({@code MethodProvider.ports}), the config check wires against them, and the engine checks that a method
 * it makes binds exactly these ({@link #differences}). A method class usually declares its ports as
 * constants and one {@code Ports} of them:
 *
 * <pre>{@code
 * static final InputPort<RecordValue> NEAREST = InputPort.of("nearest", RecordValue.class);
 * static final OutputPort<TextValue> LABEL = OutputPort.of("label", TextValue.class, Shape.text("near or far"));
 * static final Ports PORTS = Ports.of(NEAREST, LABEL);
 * }</pre>
 *
 * A type whose ports follow its params (one output per lamp) builds them from the params in a static
 * function that its constructor binds from too.
 *
 * @param inputs  the inputs, in the order listed
 * @param outputs the outputs, in the order listed
 */
public record Ports(List<InputPort<?>> inputs, List<OutputPort<?>> outputs) {

    /** An input or an output of a method type. */
    public sealed interface Port permits InputPort, OutputPort {
        String name();
    }

    public Ports {
        inputs = List.copyOf(inputs);
        outputs = List.copyOf(outputs);
        unique(inputs.stream().map(InputPort::name).toList(), "input");
        unique(outputs.stream().map(OutputPort::name).toList(), "output");
    }

    /** The ports given, inputs and outputs in any mix. */
    public static Ports of(Port... ports) {
        return of(Arrays.asList(ports));
    }

    public static Ports of(Collection<? extends Port> ports) {
        List<InputPort<?>> in = new ArrayList<>();
        List<OutputPort<?>> out = new ArrayList<>();
        for (Port p : ports) {
            switch (p) {
                case InputPort<?> i -> in.add(i);
                case OutputPort<?> o -> out.add(o);
            }
        }
        return new Ports(in, out);
    }

    /** These ports and {@code more}. */
    public Ports plus(Collection<? extends Port> more) {
        List<Port> all = new ArrayList<>(inputs);
        all.addAll(outputs);
        all.addAll(more);
        return of(all);
    }

    public Optional<InputPort<?>> input(String name) {
        return inputs.stream().filter(i -> i.name().equals(name)).findFirst();
    }

    public Optional<OutputPort<?>> output(String name) {
        return outputs.stream().filter(o -> o.name().equals(name)).findFirst();
    }

    /**
     * How {@code bound} — the ports a made method declared — differs from these, one sentence per port
     * (missing, extra or different); empty when they are the same, in whatever order.
     */
    public List<String> differences(Ports bound) {
        List<String> found = new ArrayList<>();
        compare(index(inputs), index(bound.inputs), found);
        compare(index(outputs), index(bound.outputs), found);
        return found;
    }

    private static <T extends Port> Map<String, T> index(List<T> ports) {
        Map<String, T> m = new LinkedHashMap<>();
        ports.forEach(p -> m.put(p.name(), p));
        return m;
    }

    private static <T extends Port> void compare(Map<String, T> listed, Map<String, T> bound, List<String> found) {
        listed.forEach((name, p) -> {
            T b = bound.get(name);
            if (b == null) {
                found.add(p + " is listed but not bound");
            } else if (!b.equals(p)) {
                found.add(p + " is listed as " + describe(p) + " but bound as " + describe(b));
            }
        });
        bound.forEach((name, b) -> {
            if (!listed.containsKey(name)) {
                found.add(b + " is bound but not listed");
            }
        });
    }

    private static String describe(Port p) {
        return switch (p) {
            case InputPort<?> i -> i.type().getSimpleName() + ", " + i.delivery() + (i.optional() ? ", optional" : "");
            case OutputPort<?> o -> o.type().getSimpleName() + ", " + o.shape();
        };
    }

    private static void unique(List<String> names, String what) {
        Set<String> seen = new HashSet<>();
        for (String n : names) {
            if (!seen.add(n)) {
                throw new IllegalArgumentException(what + " '" + n + "' is listed twice");
            }
        }
    }
}
