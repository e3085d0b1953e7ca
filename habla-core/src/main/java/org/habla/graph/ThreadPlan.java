package org.habla.graph;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.habla.config.HablaConfig;
import org.habla.config.InterfaceConfig;
import org.habla.config.MethodConfig;
import org.habla.config.Source;
import org.habla.config.ThreadChoice;
import org.habla.driver.Driver;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;

/**
 * Which thread each method of a config runs on, read from the config, the method types and the interfaces' drivers
 * alone (nothing is made or connected), so that the engine, {@code habla graph} and the monitor say the same.
 *
 * <p>A method runs <em>inline</em> — on the thread that delivers to it, in the same pass as the method before it,
 * with no queue hand-off between them — when all of this holds; otherwise it has a thread of its own
 * ({@code habla-method-ID}) and the reason is kept:
 * <ul>
 *   <li>its type is {@linkplain MethodProvider#light light} (no ticks, no background work, nothing that blocks),
 *       and the config leaves the choice to the engine ({@code "thread"} not {@code "own"});</li>
 *   <li>it runs in the daemon, writes no interface command (a command is socket I/O), and closes no wiring cycle;</li>
 *   <li>every input is wired, and all of them are fed from one and the same thread: the reader of an interface
 *       with a single connection (its {@code link} channel is told from several threads), or the thread of the
 *       method whose output it reads. Control clients write from threads of their own, and a method on a worker
 *       publishes from its link's thread and, on a fallback, from the daemon's copy: inputs fed by them have
 *       more than one thread.</li>
 * </ul>
 * A chain of light methods behind one connection thus runs whole on that connection's reader thread.
 */
public final class ThreadPlan {

    /**
     * How one method runs.
     *
     * @param light  whether its type is light (then it runs no background work, wherever it runs)
     * @param inline whether it runs on the thread that delivers to it
     * @param thread the name of the thread it runs on: its own {@code habla-method-ID}, or the one it shares
     * @param reason why: what feeds it, or what keeps it on a thread of its own
     */
    public record Choice(String methodId, boolean light, boolean inline, String thread, String reason) {

        /** Whose thread it runs on, in words: {@code @robot/main's reader}, {@code sonar's thread}. */
        public String where() {
            if (thread.startsWith(ReconnectingLink.THREAD_PREFIX)) {
                return "@" + thread.substring(ReconnectingLink.THREAD_PREFIX.length()) + "'s reader";
            }
            if (thread.startsWith(MethodScheduler.THREAD_PREFIX)) {
                return thread.substring(MethodScheduler.THREAD_PREFIX.length()) + "'s thread";
            }
            return thread;
        }

        /** A thread of its own, for {@code reason}. */
        static Choice own(String methodId, boolean light, String reason) {
            return new Choice(methodId, light, false, MethodScheduler.THREAD_PREFIX + methodId, reason);
        }
    }

    /** What feeds an input: one thread (by name), or several (thread null), and which. */
    private record Feed(String thread, String what) {
    }

    private final Map<String, Choice> choices;

    private ThreadPlan(Map<String, Choice> choices) {
        this.choices = choices;
    }

    /** The plan of a checked config; makes each interface's driver to count its connections (connects nothing). */
    public static ThreadPlan of(HablaConfig config, PluginRegistry registry) {
        Map<String, List<String>> connections = new HashMap<>();
        for (InterfaceConfig ic : config.interfaces()) {
            connections.put(ic.id(), LiveDriver.create(registry, ic).connectionNames());
        }
        Set<String> light = new HashSet<>();
        for (MethodConfig mc : config.methods()) {
            if (registry.method(mc.type()).map(MethodProvider::light).orElse(false)) {
                light.add(mc.id());
            }
        }
        return new ThreadPlan(new Planner(config, connections, light).plan());
    }

    /** How {@code methodId} runs. */
    public Choice choice(String methodId) {
        Choice c = choices.get(methodId);
        if (c == null) {
            throw new IllegalArgumentException("no method '" + methodId + "' in the plan");
        }
        return c;
    }

    /** Every method's choice, in config order. */
    public List<Choice> choices() {
        return List.copyOf(choices.values());
    }

    /**
     * The threads that run more than their own work, each with the methods it runs in config order: a link's reader
     * with the methods inline on it, a method's own thread with itself first and then the methods inline on it.
     */
    public Map<String, List<String>> shared() {
        Map<String, List<String>> byThread = new LinkedHashMap<>();
        for (Choice c : choices.values()) {
            if (c.inline()) {
                byThread.computeIfAbsent(c.thread(), t -> new ArrayList<>()).add(c.methodId());
            }
        }
        byThread.forEach((thread, methods) -> {
            if (thread.startsWith(MethodScheduler.THREAD_PREFIX)) {
                methods.add(0, thread.substring(MethodScheduler.THREAD_PREFIX.length()));
            }
        });
        return byThread;
    }

    /** Works the choices out method by method, each after the methods that feed it. */
    private static final class Planner {
        private final HablaConfig config;
        private final Map<String, List<String>> connections;
        private final Set<String> light;
        private final Map<String, Choice> done = new HashMap<>();
        private final Set<String> deciding = new LinkedHashSet<>();

        Planner(HablaConfig config, Map<String, List<String>> connections, Set<String> light) {
            this.config = config;
            this.connections = connections;
            this.light = light;
        }

        Map<String, Choice> plan() {
            Map<String, Choice> plan = new LinkedHashMap<>();
            for (MethodConfig mc : config.methods()) {
                plan.put(mc.id(), decide(mc.id()));
            }
            return plan;
        }

        private Choice decide(String id) {
            Choice known = done.get(id);
            if (known != null) {
                return known;
            }
            if (!deciding.add(id)) {
                return Choice.own(id, light.contains(id), "it is on a wiring cycle");
            }
            Choice c = decide(config.method(id).orElseThrow());
            deciding.remove(id);
            done.put(id, c);
            return c;
        }

        private Choice decide(MethodConfig mc) {
            String id = mc.id();
            if (mc.thread() == ThreadChoice.OWN) {
                return Choice.own(id, light.contains(id), "the config asks for a thread of its own");
            }
            if (!light.contains(id)) {
                return Choice.own(id, false, "its type is not light");
            }
            if (mc.host().isPresent()) {
                return Choice.own(id, light.contains(id), "it runs on a worker");
            }
            if (!mc.commands().isEmpty()) {
                return Choice.own(id, light.contains(id), "it writes interface commands");
            }
            if (!config.cycleInputs(id).isEmpty()) {
                return Choice.own(id, light.contains(id), "it closes a wiring cycle");
            }
            if (mc.inputs().isEmpty()) {
                return Choice.own(id, light.contains(id), "no input is wired");
            }
            Set<String> threads = new LinkedHashSet<>();
            for (Source s : mc.inputs().values()) {
                Feed f = feed(s);
                if (f.thread() == null) {
                    return Choice.own(id, true, f.what());
                }
                threads.add(f.thread());
            }
            if (threads.size() > 1) {
                return Choice.own(id, true, "its inputs come from " + threads.size() + " threads ("
                        + String.join(", ", threads) + ")");
            }
            String thread = threads.iterator().next();
            return new Choice(id, true, true, thread, "light, and fed only by " + thread);
        }

        private Feed feed(Source s) {
            return switch (s) {
                case Source.Control c -> new Feed(null, "control clients write to it, each from a thread of its own");
                case Source.Channel ch -> {
                    List<String> names = connections.getOrDefault(ch.interfaceId(), List.of());
                    if (ch.channel().equals(Driver.LINK_CHANNEL.name())) {
                        yield new Feed(null, "it reads " + ch.text() + ", which is told from several threads");
                    }
                    if (names.size() != 1) {
                        yield new Feed(null, "it reads " + ch.text() + ", and readings of " + ch.interfaceId()
                                + " come from " + names.size() + " connections");
                    }
                    yield new Feed(ReconnectingLink.THREAD_PREFIX + ch.interfaceId() + "/" + names.get(0), ch.text());
                }
                case Source.MethodOutput mo -> {
                    MethodConfig from = config.method(mo.methodId()).orElseThrow();
                    if (from.host().isPresent()) {
                        yield new Feed(null, "it reads " + mo.methodId() + ", which runs on a worker and publishes"
                                + " from its link's thread or, on a fallback, from the daemon's copy");
                    }
                    yield new Feed(decide(mo.methodId()).thread(), mo.methodId() + "." + mo.output());
                }
            };
        }
    }
}
