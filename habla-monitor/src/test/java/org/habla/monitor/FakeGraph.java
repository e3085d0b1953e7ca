package org.habla.monitor;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import org.habla.daemon.LiveGraph;
import org.habla.graph.OutputInfo;
import org.habla.method.Shape;
import org.habla.sample.Payload;
import org.habla.sample.Sample;

/** A running graph as the monitor sees it, whose outputs a test emits by hand (on the test's thread). */
final class FakeGraph implements LiveGraph {

    private final List<OutputInfo> outputs;
    private final List<Consumer<Sample>> watchers = new CopyOnWriteArrayList<>();
    private long sequence;

    FakeGraph(OutputInfo... outputs) {
        this.outputs = List.of(outputs);
    }

    static OutputInfo output(String method, String name, Shape shape) {
        return new OutputInfo(method, name, shape);
    }

    /** Emits a value on {@code method.output} as the engine would, to every watcher. */
    void emit(String producer, Payload value) {
        Sample s = new Sample(value, producer, ++sequence, System.currentTimeMillis() * 1000, false);
        watchers.forEach(w -> w.accept(s));
    }

    @Override
    public ObjectNode status() {
        ObjectNode n = JsonNodeFactory.instance.objectNode().put("system", "fake").put("uptimeS", 1.0);
        n.putObject("watchdog").put("timeoutMs", 0).put("tripped", false).put("trips", 0);
        n.putArray("interfaces").addObject().put("id", "robot").put("driver", "fake").put("up", true)
                .put("sinceMicros", 1);
        n.putArray("methods").addObject().put("id", "m").put("type", "fake").put("state", "RUNNING")
                .put("ready", true).put("stale", false);
        n.putArray("sockets");
        return n;
    }

    @Override
    public java.util.Map<String, List<String>> inputs() {
        return java.util.Map.of();
    }

    @Override
    public List<OutputInfo> outputs() {
        return outputs;
    }

    @Override
    public AutoCloseable watchOutputs(Consumer<Sample> watcher) {
        watchers.add(watcher);
        return () -> watchers.remove(watcher);
    }
}
