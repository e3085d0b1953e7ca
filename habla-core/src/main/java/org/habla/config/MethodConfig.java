package org.habla.config;

import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.habla.method.Layer;
import org.habla.net.Expose;

/**
 * One method of the graph.
 *
 * @param id       the id used in references ({@code "id.output"})
 * @param type     the method type name
 * @param layer    the layer it is placed in
 * @param inputs   input name → where its samples come from
 * @param commands output name → the interface command channel it writes (sensors &amp; actuators layer only)
 * @param params   the type's own params record, already validated
 * @param expose   the method's control socket, if it has one (virtual layer only)
 * @param host     the worker that runs it ({@code "host:port"}), if not the daemon itself
 * @param fallback what happens while that worker is lost ({@link Fallback#NONE} for a method without host)
 * @param feedback the inputs the config declares to close a wiring cycle ({@link WiringCycles})
 * @param thread   whether the engine may run the method on the thread that delivers to it, or gives it its own
 */
public record MethodConfig(String id, String type, Layer layer, Map<String, Source> inputs,
        Map<String, ChannelRef> commands, Record params, Optional<Expose> expose, Optional<String> host,
        Fallback fallback, Set<String> feedback, ThreadChoice thread) {

    public MethodConfig {
        inputs = Map.copyOf(inputs);
        commands = Map.copyOf(commands);
        java.util.Objects.requireNonNull(fallback, "fallback");
        feedback = Set.copyOf(feedback);
        java.util.Objects.requireNonNull(thread, "thread");
    }

    /** A method whose thread the engine chooses. */
    public MethodConfig(String id, String type, Layer layer, Map<String, Source> inputs,
            Map<String, ChannelRef> commands, Record params, Optional<Expose> expose, Optional<String> host,
            Fallback fallback, Set<String> feedback) {
        this(id, type, layer, inputs, commands, params, expose, host, fallback, feedback, ThreadChoice.AUTO);
    }

    /** A method that closes no wiring cycle. */
    public MethodConfig(String id, String type, Layer layer, Map<String, Source> inputs,
            Map<String, ChannelRef> commands, Record params, Optional<Expose> expose, Optional<String> host,
            Fallback fallback) {
        this(id, type, layer, inputs, commands, params, expose, host, fallback, Set.of());
    }

    /** A method with no fallback: its outputs stay stale while a worker it is placed on is lost. */
    public MethodConfig(String id, String type, Layer layer, Map<String, Source> inputs,
            Map<String, ChannelRef> commands, Record params, Optional<Expose> expose, Optional<String> host) {
        this(id, type, layer, inputs, commands, params, expose, host, Fallback.NONE);
    }
}
