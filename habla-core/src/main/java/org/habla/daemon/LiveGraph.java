package org.habla.daemon;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.habla.graph.OutputInfo;
import org.habla.sample.Sample;

/**
 * What a product beside a daemon (the live monitor, a {@link DaemonExtension}) reads of it, and all it reads: the
 * status snapshot, the methods' outputs and a tap on what they emit. Nothing here can change the graph, so nothing
 * such a product does can drive the robot.
 */
public interface LiveGraph {

    /** The daemon's status snapshot, as {@code habla status} shows it. */
    ObjectNode status();

    /** The producers ({@code method.output}) each method reads, by method id. */
    Map<String, List<String>> inputs();

    /** Every method output, in config order. */
    List<OutputInfo> outputs();

    /**
     * Hands every emitted sample to {@code watcher} on the emitting (engine) thread until the handle is closed;
     * the watcher must return at once.
     */
    AutoCloseable watchOutputs(Consumer<Sample> watcher);
}
