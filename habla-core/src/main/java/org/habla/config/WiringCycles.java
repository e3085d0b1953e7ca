package org.habla.config;

import java.util.ArrayList;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Predicate;

/**
 * The wires between the methods of a config and the cycles they close. A wire lies on a cycle when the method
 * it leaves can be reached again from the method it enters (both ends are in one strongly connected component
 * of the method graph). A sample sent round a cycle can come back for ever, so a config must declare each
 * cycle ({@code "feedback"} on one of its inputs), and the engine delivers every wire on a cycle as
 * {@code latest}: what circles is at most one sample per input, never a growing queue.
 */
public final class WiringCycles {

    /** A wire from one method's output to an input of a method (possibly the same one). */
    public record Wire(String fromMethod, String output, String toMethod, String input) {
    }

    private final List<String> methods;
    private final List<Wire> wires;
    private final Map<String, Integer> component = new HashMap<>();
    private final Set<Integer> cyclic = new HashSet<>();

    private WiringCycles(List<String> methods, List<Wire> wires) {
        this.methods = methods;
        this.wires = wires;
        new Components().run();
    }

    /** The wires of a checked config. */
    public static WiringCycles of(List<MethodConfig> methods) {
        Map<String, Map<String, Source>> inputs = new LinkedHashMap<>();
        methods.forEach(m -> inputs.put(m.id(), m.inputs()));
        return of(inputs);
    }

    /** The wires of {@code inputs} (method id → input name → source), in that map's order. */
    static WiringCycles of(Map<String, Map<String, Source>> inputs) {
        List<Wire> wires = new ArrayList<>();
        inputs.forEach((to, sources) -> sources.forEach((input, source) -> {
            if (source instanceof Source.MethodOutput mo && inputs.containsKey(mo.methodId())) {
                wires.add(new Wire(mo.methodId(), mo.output(), to, input));
            }
        }));
        return new WiringCycles(List.copyOf(inputs.keySet()), List.copyOf(wires));
    }

    /** Whether {@code wire} lies on a cycle. */
    public boolean onCycle(Wire wire) {
        Integer c = component.get(wire.fromMethod());
        return c != null && c.equals(component.get(wire.toMethod())) && cyclic.contains(c);
    }

    /** The inputs of {@code methodId} whose wires lie on a cycle. */
    public Set<String> cycleInputs(String methodId) {
        Set<String> out = new LinkedHashSet<>();
        wires.stream().filter(w -> w.toMethod().equals(methodId) && onCycle(w)).forEach(w -> out.add(w.input()));
        return out;
    }

    /** The wire into {@code methodId}'s {@code input}, if that input reads another method's output. */
    Optional<Wire> wireInto(String methodId, String input) {
        return wires.stream().filter(w -> w.toMethod().equals(methodId) && w.input().equals(input)).findFirst();
    }

    /**
     * A cycle left when the {@code declared} wires are taken out, as its wires in order; the last one closes it.
     * Methods and wires are visited in config order, so the same config always names the same cycle.
     */
    Optional<List<Wire>> undeclaredCycle(Predicate<Wire> declared) {
        Map<String, List<Wire>> out = new HashMap<>();
        wires.stream().filter(declared.negate()).forEach(w -> out.computeIfAbsent(w.fromMethod(), k -> new ArrayList<>()).add(w));
        Map<String, Integer> state = new HashMap<>();
        for (String start : methods) {
            if (state.containsKey(start)) {
                continue;
            }
            Deque<Wire> path = new ArrayDeque<>();
            Optional<List<Wire>> found = search(start, out, state, path);
            if (found.isPresent()) {
                return found;
            }
        }
        return Optional.empty();
    }

    private static final int ON_PATH = 1;
    private static final int DONE = 2;

    private static Optional<List<Wire>> search(String method, Map<String, List<Wire>> out, Map<String, Integer> state,
            Deque<Wire> path) {
        state.put(method, ON_PATH);
        for (Wire w : out.getOrDefault(method, List.of())) {
            Integer s = state.get(w.toMethod());
            if (s == null) {
                path.addLast(w);
                Optional<List<Wire>> found = search(w.toMethod(), out, state, path);
                if (found.isPresent()) {
                    return found;
                }
                path.removeLast();
            } else if (s == ON_PATH) {
                List<Wire> cycle = new ArrayList<>();
                boolean in = false;
                for (Wire p : path) {
                    in |= p.fromMethod().equals(w.toMethod());
                    if (in) {
                        cycle.add(p);
                    }
                }
                cycle.add(w);
                return Optional.of(cycle);
            }
        }
        state.put(method, DONE);
        return Optional.empty();
    }

    /** Tarjan's strongly connected components, numbering each method's component. */
    private final class Components {
        private final Map<String, List<String>> next = new HashMap<>();
        private final Map<String, Integer> index = new HashMap<>();
        private final Map<String, Integer> low = new HashMap<>();
        private final Deque<String> stack = new ArrayDeque<>();
        private final Set<String> onStack = new HashSet<>();
        private int counter;
        private int components;

        void run() {
            for (Wire w : wires) {
                next.computeIfAbsent(w.fromMethod(), k -> new ArrayList<>()).add(w.toMethod());
            }
            for (String m : methods) {
                if (!index.containsKey(m)) {
                    visit(m);
                }
            }
            wires.stream().filter(w -> w.fromMethod().equals(w.toMethod()))
                    .forEach(w -> cyclic.add(component.get(w.fromMethod())));
        }

        private void visit(String m) {
            index.put(m, counter);
            low.put(m, counter);
            counter++;
            stack.push(m);
            onStack.add(m);
            for (String n : next.getOrDefault(m, List.of())) {
                if (!index.containsKey(n)) {
                    visit(n);
                    low.put(m, Math.min(low.get(m), low.get(n)));
                } else if (onStack.contains(n)) {
                    low.put(m, Math.min(low.get(m), index.get(n)));
                }
            }
            if (low.get(m).equals(index.get(m))) {
                int c = components++;
                int size = 0;
                String popped;
                do {
                    popped = stack.pop();
                    onStack.remove(popped);
                    component.put(popped, c);
                    size++;
                } while (!popped.equals(m));
                if (size > 1) {
                    cyclic.add(c);
                }
            }
        }
    }
}
