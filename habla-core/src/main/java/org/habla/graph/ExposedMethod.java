package org.habla.graph;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.function.Function;
import org.habla.net.Expose;
import org.habla.method.ControlNotice;
import org.habla.method.Input;
import org.habla.method.Layer;
import org.habla.method.MethodState;
import org.habla.method.Output;
import org.habla.method.Shape;
import org.habla.net.ControlLease;
import org.habla.net.ControlPoint;
import org.habla.sample.Payload;
import org.habla.sample.Sample;

/** A method with a control socket, as the engine shows it to its control server. */
final class ExposedMethod implements ControlPoint {

    private final MethodRunner runner;
    private final Expose expose;
    private final List<Input<?>> controlInputs;
    /** What a control write to each control input is handed to, by the input's declaration index. */
    private final InputEntry[] entries;
    private final MotionWatchdog watchdog;
    private final GraphTap tap;
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();
    /** The sequence number of the last value written to each input, by the input's declaration index. */
    private final AtomicLongArray controlSequences;
    private final boolean actuating;
    private final ControlLease lease;
    /** The producer a written value's sample names ({@code control:SOCKET}). */
    private final String controlProducer;
    private final Function<Output<?>, Shape> shapes;

    /**
     * @param controlled the inputs a control client writes, each with what a write is handed to
     * @param actuating  whether values written here can reach a command channel
     * @param shapes     the shape each output shows with what feeds it
     */
    ExposedMethod(MethodRunner runner, Expose expose, Map<Input<?>, InputEntry> controlled, MotionWatchdog watchdog,
            GraphTap tap, boolean actuating, Function<Output<?>, Shape> shapes) {
        List<Input<?>> controlInputs = runner.method().inputs().stream().filter(controlled::containsKey).toList();
        this.entries = new InputEntry[runner.method().inputs().size()];
        controlled.forEach((in, entry) -> entries[in.index()] = entry);
        this.runner = runner;
        this.shapes = shapes;
        this.actuating = actuating && !controlInputs.isEmpty();
        this.lease = this.actuating ? new ControlLease(expose.name(), watchdog.timeoutMillis(), runner::nowMicros,
                this::writerLeft, line -> listeners.forEach(l -> l.onControl(line))) : null;
        this.expose = expose;
        this.controlProducer = "control:" + expose.name();
        this.controlInputs = List.copyOf(controlInputs);
        this.controlSequences = new AtomicLongArray(runner.method().inputs().size());
        this.watchdog = watchdog;
        this.tap = tap;
        for (Output<?> out : runner.method().outputs()) {
            runner.port(out).subscribe(sample -> {
                tap.output(runner.id(), out.name(), sample);
                for (Listener l : listeners) {
                    l.onSample(out, sample);
                }
            });
        }
    }

    Expose expose() {
        return expose;
    }

    @Override
    public String name() {
        return expose.name();
    }

    @Override
    public String methodId() {
        return runner.id();
    }

    @Override
    public Layer layer() {
        return runner.method().layer();
    }

    @Override
    public List<Output<?>> outputs() {
        return runner.method().outputs();
    }

    @Override
    public Shape shapeOf(Output<?> output) {
        return shapes.apply(output);
    }

    @Override
    public List<Input<?>> controlInputs() {
        return controlInputs;
    }

    @Override
    public Optional<ControlLease> lease() {
        return Optional.ofNullable(lease);
    }

    @Override
    public Map<String, Sample> latest() {
        Map<String, Sample> m = new HashMap<>();
        for (Output<?> out : runner.method().outputs()) {
            Sample s = runner.port(out).latest();
            if (s != null) {
                m.put(out.name(), s);
            }
        }
        return m;
    }

    @Override
    public boolean stale() {
        return runner.stale();
    }

    /** Tells every client what a method its values reach has to say about them. */
    void notice(ControlNotice notice) {
        for (Listener l : listeners) {
            l.onNotice(notice);
        }
    }

    /** Tells every client that staleness changed. */
    void staleChanged(boolean stale, String why) {
        for (Listener l : listeners) {
            l.onStale(stale, why);
        }
    }

    @Override
    public Subscription subscribe(Listener listener) {
        listeners.add(listener);
        return () -> listeners.remove(listener);
    }

    @Override
    public void write(Input<?> input, Payload value) throws Rejected {
        if (!controlInputs.contains(input)) {
            throw new Rejected("unknown_input", "'" + input.name() + "' is not a control input of " + runner.id());
        }
        if (!input.accepts(value)) {
            throw new Rejected("bad_value", "input '" + input.name() + "' takes " + input.kind().wireName()
                    + ", got " + value.kind().wireName());
        }
        Optional<String> refused = input.refusal(value);
        if (refused.isPresent()) {
            throw new Rejected("bad_value", refused.get());
        }
        MethodState state = runner.state();
        if (state != MethodState.RUNNING) {
            throw new Rejected("method_unavailable", "method " + runner.id() + " is " + state
                    + (runner.failure().isEmpty() ? "" : ": " + runner.failure()));
        }
        long seq = controlSequences.incrementAndGet(input.index());
        if (actuating) {
            watchdog.controlWrite();
        }
        Sample sample = new Sample(value, controlProducer, seq, runner.nowMicros(), false);
        tap.control(expose.name(), input.name(), sample);
        if (!entries[input.index()].offer(sample)) {
            throw new Rejected("queue_full", "input '" + input.name() + "' of " + runner.id()
                    + " is full (" + input.delivery().capacity() + " waiting); value dropped");
        }
    }

    @Override
    public void writerLeft() {
        if (actuating) {
            tap.writerLeft(expose.name());
            watchdog.writerLeft();
        }
    }

}
