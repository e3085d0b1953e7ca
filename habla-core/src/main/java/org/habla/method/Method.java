package org.habla.method;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.function.Consumer;
import java.util.function.Function;
import org.habla.driver.ChannelDescriptor;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A method: one small unit of the HABLA's three-layer graph, with named typed inputs and outputs. Subclass the
 * base class of its layer — {@link SensorActuatorMethod}, {@link ProcessingMethod} or {@link VirtualMethod} —
 * declare its ports once as constants ({@link InputPort}, {@link OutputPort}, listed in one {@link Ports} that
 * the type's provider hands to HABLA), bind them, and handle samples:
 *
 * <pre>{@code
 * public final class Threshold extends ProcessingMethod {
 *     static final InputPort<RecordValue> NEAREST = InputPort.of("nearest", RecordValue.class, Delivery.latest());
 *     static final OutputPort<TextValue> LABEL = OutputPort.of("label", TextValue.class,
 *             Shape.text("near or far, emitted when it changes"));
 *     static final Ports PORTS = Ports.of(NEAREST, LABEL);
 *
 *     private final Output<TextValue> label = output(LABEL);
 *     private final Input<RecordValue> nearest = input(NEAREST, this::onNearest);
 *     private final ThresholdParams params;
 *     private String current = "";
 *
 *     public Threshold(ThresholdParams params) {
 *         this.params = params;
 *     }
 *
 *     private void onNearest(RecordValue obstacle, Sample s) {
 *         double d = obstacle.number("distanceM");
 *         String next = d < params.nearM() ? "near" : d > params.farM() ? "far" : current;
 *         if (!next.equals(current)) {
 *             current = next;
 *             emit(label, new TextValue(next));
 *         }
 *     }
 * }
 * }</pre>
 *
 * (the whole plugin, with its params record, provider and test, is {@code examples/custom-method}).
 *
 * <h2>Threading contract</h2>
 * The engine hands a method one message at a time — a sample, a tick or the result of background
 * work — each after the previous one has returned, so method code needs no locks: keep state in plain
 * fields. It never sleeps, starts a thread or opens a socket; slow work goes through {@link #background},
 * periodic work through {@link #tickEvery}, time through {@link #nowMicros}. The engine chooses the thread
 * that hands over the messages: the method's own, or, for a light type ({@code MethodProvider.light}: no
 * ticks, no background work, microseconds) fed from one thread, that thread, which runs it and the light
 * methods after it in one pass; so {@link #emit} may return after those have handled the value, and a value
 * that comes back meanwhile waits in the input. Inputs keep their delivery ({@code latest}, {@code queue}).
 *
 * <h2>Life cycle</h2>
 * The engine owns it, through a {@link MethodLifecycle} that a method never sees:
 * {@code NEW → ATTACHED → RUNNING → STOPPED}; an exception thrown by a hook puts the method in
 * {@code FAILED} with one log line, and a failed method is handed nothing more. Subclasses fill the hooks
 * {@link #onStart}, {@link #onSample}, {@link #onTick} and {@link #onStop}; a method that keeps motion
 * state (a held action, a speed ramp) also fills {@link #onMotionStopped}. What a method author calls is
 * above; what the engine reads of a method — its id, ports and tick period — is below.
 */
public abstract sealed class Method permits SensorActuatorMethod, ProcessingMethod, VirtualMethod {

    private final List<Input<?>> inputs = new ArrayList<>();
    private final List<Output<?>> outputs = new ArrayList<>();
    private Duration tickPeriod;
    /** The engine's handle on this method, set once when it is attached ({@link MethodLifecycle#attach}). */
    volatile MethodLifecycle lifecycle;
    /** The source time of the message being handled, set by the life cycle before each hook runs. */
    long currentSourceMicros;

    Method() {
    }

    /** The layer this method belongs to. */
    public abstract Layer layer();

    // ---------------------------------------------------------------- declarations (subclass construction)

    /** Binds an input port of this method's type, with the handler that takes its samples. */
    protected final <P extends Payload> Input<P> input(InputPort<P> port, InputHandler<P> handler) {
        return addInput(new Input<>(port, Objects.requireNonNull(handler, "handler"), null));
    }

    /**
     * Binds an input port whose values a control client may write, with a check that names why a value is
     * refused ({@code null} when it is taken). The check runs on the client's thread before the value is
     * queued, so it must look only at the value and at fields fixed at construction (params), never at
     * state the handler changes. The handler still sees only values the check let through from control,
     * but must treat values from wired methods on its own.
     */
    protected final <P extends Payload> Input<P> input(InputPort<P> port, InputHandler<P> handler,
            Function<? super P, String> refusal) {
        return addInput(new Input<>(port, Objects.requireNonNull(handler, "handler"),
                Objects.requireNonNull(refusal, "refusal")));
    }

    /** Binds an input port whose samples go to {@link #onSample}. */
    protected final <P extends Payload> Input<P> input(InputPort<P> port) {
        return addInput(new Input<>(port, null, null));
    }

    private <P extends Payload> Input<P> addInput(Input<P> in) {
        requireNew("declare an input");
        for (Input<?> other : inputs) {
            if (other.name().equals(in.name())) {
                throw new IllegalArgumentException("input '" + in.name() + "' is declared twice");
            }
        }
        in.declaredAt(inputs.size());
        inputs.add(in);
        return in;
    }

    /** Binds an output port of this method's type. */
    protected final <P extends Payload> Output<P> output(OutputPort<P> port) {
        requireNew("declare an output");
        for (Output<?> other : outputs) {
            if (other.name().equals(port.name())) {
                throw new IllegalArgumentException("output '" + port.name() + "' is declared twice");
            }
        }
        Output<P> out = new Output<>(port);
        out.declaredAt(outputs.size());
        outputs.add(out);
        return out;
    }

    /** Asks the engine for {@link #onTick} every {@code period}; call from the constructor. */
    protected final void tickEvery(Duration period) {
        requireNew("ask for ticks");
        if (period.isNegative() || period.isZero() || period.toMillis() > 3_600_000) {
            throw new IllegalArgumentException("tick period must be within (0, 1 h], was " + period);
        }
        this.tickPeriod = period;
    }

    // ---------------------------------------------------------------- hooks

    /** Called once before any sample; may start background work. */
    protected void onStart() throws Exception {
    }

    /** Called for a sample of an input declared without a handler. */
    protected void onSample(Input<?> input, Sample sample) throws Exception {
        throw new IllegalStateException(getClass().getSimpleName() + " declares " + input
                + " without a handler and does not override onSample");
    }

    /** Called every tick period, if the method asked for ticks. */
    protected void onTick(long nowMicros) throws Exception {
    }

    /** Called once when the engine stops; release what {@link #onStart} took. */
    protected void onStop() throws Exception {
    }

    /**
     * Called when the engine stopped the robot behind the method's back — the motion watchdog tripped — and
     * again when control comes back after such a stop, each time before the method handles anything newer.
     * Only methods whose outputs lead to a motion command channel are called. The robot stands: forget any
     * motion being held or ramped, so that what the method says next is what the robot does (a method that
     * emits only changes would otherwise stay silent when asked again for the motion it last sent).
     */
    protected void onMotionStopped() throws Exception {
    }

    // ---------------------------------------------------------------- helpers for method code

    /** Publishes a value, stamped with the source time of the message being handled. */
    protected final <P extends Payload> void emit(Output<P> output, P value) {
        emit(output, value, currentSourceMicros);
    }

    /** Publishes a value stamped with an explicit source time. */
    protected final <P extends Payload> void emit(Output<P> output, P value, long sourceMicros) {
        if (output.index() < 0 || output.index() >= outputs.size() || outputs.get(output.index()) != output) {
            throw new IllegalArgumentException(output + " is not an output of " + id());
        }
        if (!output.shape().admits(value)) {
            throw new IllegalArgumentException(id() + "." + output.name() + " carries "
                    + output.shape().form().getSimpleName() + " records, not "
                    + ((RecordValue) value).carriesForm().getClass().getSimpleName());
        }
        context().emit(output, Objects.requireNonNull(value, "value"), sourceMicros);
    }

    /** The engine clock, in microseconds since the epoch. */
    protected final long nowMicros() {
        return context().nowMicros();
    }

    /** Whether a link, device or worker its inputs come from is down now (a command sent meanwhile may not arrive). */
    protected final boolean stale() {
        return context().stale();
    }

    /** The source time of the message being handled (the raw reading's time, or the tick's time). */
    protected final long sourceMicros() {
        return currentSourceMicros;
    }

    /** The interface channel an input is wired to, with its metadata (e.g. sonar poses). */
    protected final Optional<ChannelDescriptor> channelOf(Input<?> input) {
        return context().channelOf(input);
    }

    /**
     * The interface command channel an output is written to (the config's {@code commands}), with its
     * metadata (e.g. a base's speed limits); empty when the output goes to methods only.
     */
    protected final Optional<ChannelDescriptor> commandChannelOf(Output<?> output) {
        return context().commandChannelOf(output);
    }

    /**
     * Tells the control clients whose values reach this method something about what they asked — a move vetoed,
     * and why — as a {@code notice} line on their sockets, stamped with the source time of the message being
     * handled (for a value a client wrote, the time of that write). See {@link ControlNotice}.
     */
    protected final void tellControl(String notice, String message, org.habla.sample.RecordValue detail) {
        context().tellControl(new ControlNotice(notice, id(), message, detail, currentSourceMicros));
    }

    /** Reports whether the method can do its work yet. */
    protected final void readiness(boolean ready, String detail) {
        context().readiness(ready, detail);
    }

    /** Runs slow work away from the method's turn; {@code done} later runs as a turn of its own. */
    protected final <T> void background(String what, Callable<T> task, Consumer<T> done) {
        context().background(what, task, done);
    }

    /** The logger of the concrete method class. */
    protected final Logger log() {
        return LoggerFactory.getLogger(getClass());
    }

    // ---------------------------------------------------------------- the engine's side

    /** The method's id, once attached. */
    public final String id() {
        MethodLifecycle l = lifecycle;
        return l == null ? getClass().getSimpleName() : l.context().methodId();
    }

    public final List<Input<?>> inputs() {
        return Collections.unmodifiableList(inputs);
    }

    public final List<Output<?>> outputs() {
        return Collections.unmodifiableList(outputs);
    }

    public final Optional<Input<?>> input(String name) {
        return inputs.stream().filter(i -> i.name().equals(name)).findFirst();
    }

    public final Optional<Output<?>> output(String name) {
        return outputs.stream().filter(o -> o.name().equals(name)).findFirst();
    }

    /** The ports this method bound, to check against the ones its type lists ({@link Ports#differences}). */
    public final Ports boundPorts() {
        return new Ports(inputs.stream().<InputPort<?>>map(Input::port).toList(),
                outputs.stream().<OutputPort<?>>map(Output::port).toList());
    }

    /** The tick period the method asked for, if any. */
    public final Optional<Duration> tickPeriod() {
        return Optional.ofNullable(tickPeriod);
    }

    private MethodContext context() {
        MethodLifecycle l = lifecycle;
        if (l == null) {
            throw new IllegalStateException(getClass().getSimpleName() + " is not attached to an engine yet");
        }
        return l.context();
    }

    /** Ports and ticks are declared while the method is being built, before an engine attaches it. */
    private void requireNew(String action) {
        MethodLifecycle l = lifecycle;
        if (l != null) {
            throw new IllegalStateException("cannot " + action + " in state " + l.state() + " (needs NEW)");
        }
    }
}
