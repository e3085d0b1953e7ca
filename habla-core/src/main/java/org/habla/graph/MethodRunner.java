package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.ControlNotice;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.Method;
import org.habla.method.MethodContext;
import org.habla.method.MethodLifecycle;
import org.habla.method.MethodState;
import org.habla.method.Output;
import org.habla.sample.Payload;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs one method on a thread of its own: waits for samples in its input slots, ticks and
 * background results, and hands them to the method one at a time. Because every method has its
 * own thread, a slow method (speech, vision) never holds up a light one. The thread and the order of
 * messages are its {@link MethodScheduler}'s; the runner is what the method sees of the engine (its
 * {@link MethodContext}: outputs, channels, readiness, background work, notices) and what the status says of it.
 */
final class MethodRunner implements MethodContext {

    private static final Logger LOG = LoggerFactory.getLogger(MethodRunner.class);

    private final String id;
    private final String type;
    private final Method method;
    private final MethodLifecycle lifecycle;
    private final EngineClock clock;
    private final ExecutorService backgroundPool;
    private final List<InputSlot> slots = new ArrayList<>();
    private final Map<Input<?>, InputSlot> slotByInput = new HashMap<>();
    private final Map<Output<?>, OutputPort> ports = new HashMap<>();
    private final Map<Input<?>, ChannelDescriptor> channels = new HashMap<>();
    private final Map<Output<?>, ChannelDescriptor> commandChannels = new HashMap<>();
    private final AtomicBoolean tickPending = new AtomicBoolean();
    private volatile boolean stale;
    private volatile boolean ready = true;
    private volatile String readinessDetail = "";
    private AutoCloseable ticker;
    private final MethodHost.Local local;
    private final MethodScheduler scheduler;
    private volatile Consumer<ControlNotice> controlNotices = n -> { };

    static final String TICK_PREFIX = "tick:";

    private final WorkCount work;
    private final GraphTap tap;

    MethodRunner(String id, String type, Method method, EngineClock clock, ExecutorService backgroundPool,
            WorkCount work, GraphTap tap) {
        this(id, type, method, clock, backgroundPool, work, tap, java.util.Set.of());
    }

    /**
     * A runner whose inputs named in {@code latestInputs} (the wires of a declared cycle) hold only the newest
     * sample, whatever delivery the method type asks for.
     */
    MethodRunner(String id, String type, Method method, EngineClock clock, ExecutorService backgroundPool,
            WorkCount work, GraphTap tap, java.util.Set<String> latestInputs) {
        this.work = work;
        this.tap = tap;
        this.id = id;
        this.type = type;
        this.method = method;
        this.clock = clock;
        this.backgroundPool = backgroundPool;
        for (Input<?> in : method.inputs()) {
            String input = in.name();
            InputSlot slot = new InputSlot(in, latestInputs.contains(input) ? Delivery.latest() : in.delivery(),
                    this::wake, work, new InputSlot.Skips() {
                        @Override
                        public void skipped(long arrival) {
                            tap.skipped(id, input, arrival);
                        }

                        @Override
                        public boolean skippedWhenRecorded(long arrival) {
                            return tap.skippedWhenRecorded(id, input, arrival);
                        }
                    });
            slots.add(slot);
            slotByInput.put(in, slot);
        }
        for (Output<?> out : method.outputs()) {
            ports.put(out, new OutputPort(id + "." + out.name()));
        }
        lifecycle = MethodLifecycle.attach(method, this);
        local = new MethodHost.Local(lifecycle, () -> method.tickPeriod()
                .ifPresent(p -> ticker = clock.every(p.toNanos() / 1_000, this::requestTick)));
        scheduler = new MethodScheduler(id, slots, clock, work, local);
    }

    String id() {
        return id;
    }

    /** Where the method is in its life cycle. */
    MethodState state() {
        return lifecycle.state();
    }

    /** Why the method failed, or an empty string. */
    String failure() {
        return lifecycle.failure();
    }

    String type() {
        return type;
    }

    Method method() {
        return method;
    }

    InputSlot slot(Input<?> input) {
        return slotByInput.get(input);
    }

    OutputPort port(Output<?> output) {
        return ports.get(output);
    }

    void bindChannel(Input<?> input, ChannelDescriptor channel) {
        channels.put(input, channel);
    }

    void bindCommandChannel(Output<?> output, ChannelDescriptor channel) {
        commandChannels.put(output, channel);
    }

    /** The interface channels the inputs read, by input name (for a worker running the method). */
    Map<String, ChannelDescriptor> channelsByInput() {
        Map<String, ChannelDescriptor> m = new java.util.LinkedHashMap<>();
        channels.forEach((in, c) -> m.put(in.name(), c));
        return m;
    }

    /** The interface channels the outputs write, by output name (for a worker running the method). */
    Map<String, ChannelDescriptor> commandChannelsByOutput() {
        Map<String, ChannelDescriptor> m = new java.util.LinkedHashMap<>();
        commandChannels.forEach((out, c) -> m.put(out.name(), c));
        return m;
    }

    void stale(boolean isStale) {
        stale = isStale;
    }

    boolean stale() {
        return stale;
    }

    /**
     * Makes the method hear of motion resets ({@link MotionWatchdog}): before it handles anything that comes
     * after one, it is told the robot was stopped. For methods whose outputs lead to a motion channel; call
     * before {@link #start}.
     */
    void followMotionResets(LongSupplier resets) {
        scheduler.followMotionResets(resets);
    }

    /**
     * Runs the method on a worker: from now on its input samples go to {@code remote} instead of the method
     * object here, which runs only as the fallback while the worker is lost (if the config asks for one).
     * Call before {@link #start}.
     */
    void placeOn(RemotePlacement remote) {
        scheduler.host(new MethodHost.OnWorker(id, remote, local));
        if (!remote.fallsBackToLocal()) {
            ready = false;
            readinessDetail = "waiting for worker " + remote.host();
        }
    }

    boolean ready() {
        return ready;
    }

    String readinessDetail() {
        return readinessDetail;
    }

    /** Starts the method and its thread; a method placed on a worker starts here only when it must run locally. */
    void start() {
        scheduler.start();
    }

    /** A slot has a sample: wakes the method's thread. */
    private void wake() {
        scheduler.wake();
    }

    /** From the placement, on any thread: the worker was lost and the fallback is to run here. */
    void fallBackToLocal() {
        scheduler.turn(() -> {
            if (scheduler.host() instanceof MethodHost.OnWorker w) {
                w.fallBack();
            }
        });
    }

    /** Stops the thread, then the method. Waits at most {@code waitMillis} for the current turn. */
    void stop(long waitMillis) {
        closeTicker();
        scheduler.stop(waitMillis);
    }

    /**
     * The input samples the method's state reflects so far: every sample that arrived up to the last one it
     * took, on every input (a {@code latest} input's skipped samples count, as the newer one replaced them).
     */
    long consumed() {
        long n = 0;
        for (InputSlot slot : slots) {
            n += slot.consumedThrough();
        }
        return n;
    }

    /** A sample the method published on its worker, published here as if the method had emitted it. */
    void publishFromWorker(Output<?> output, Payload value, long sourceMicros) {
        emit(output, value, sourceMicros);
    }

    private void closeTicker() {
        if (ticker != null) {
            try {
                ticker.close();
            } catch (Exception e) {
                LOG.debug("ticker of {} did not close: {}", id, e.toString());
            }
        }
    }

    /** Asks for a tick; one already waiting takes this one's place (ticks never pile up behind a busy method). */
    void requestTick() {
        if (tickPending.compareAndSet(false, true)) {
            scheduler.turn(() -> {
                tickPending.set(false);
                tap.periodic(TICK_PREFIX + id, clock.nowMicros(), consumed());
                scheduler.host().tick(clock.nowMicros());
            });
        }
    }

    // ------------------------------------------------------------------ MethodContext

    @Override
    public String methodId() {
        return id;
    }

    @Override
    public long nowMicros() {
        return clock.nowMicros();
    }

    @Override
    public void emit(Output<?> output, Payload value, long sourceMicros) {
        if (!output.type().isInstance(value)) {
            throw new IllegalArgumentException(output + " of " + id + " cannot carry " + value.kind().wireName());
        }
        ports.get(output).publish(value, sourceMicros, stale);
    }

    /** Where the method's notices to control clients go (the exposed methods whose values reach it). */
    void tellControlVia(Consumer<ControlNotice> sink) {
        controlNotices = sink;
    }

    @Override
    public void tellControl(ControlNotice notice) {
        controlNotices.accept(notice);
    }

    @Override
    public Optional<ChannelDescriptor> channelOf(Input<?> input) {
        return Optional.ofNullable(channels.get(input));
    }

    @Override
    public Optional<ChannelDescriptor> commandChannelOf(Output<?> output) {
        return Optional.ofNullable(commandChannels.get(output));
    }

    @Override
    public void readiness(boolean isReady, String detail) {
        if (isReady != ready) {
            LOG.info("method {} is {}{}", id, isReady ? "ready" : "not ready",
                    detail == null || detail.isEmpty() ? "" : ": " + detail);
        }
        ready = isReady;
        readinessDetail = detail == null ? "" : detail;
    }

    @Override
    public <T> void background(String what, Callable<T> task, Consumer<T> done) {
        work.begin();
        try {
            backgroundPool.execute(() -> {
                try {
                    T result = task.call();
                    scheduler.turn(() -> lifecycle.runTurn(what, () -> done.accept(result)));
                } catch (Exception | LinkageError e) {
                    scheduler.turn(() -> lifecycle.fail(what, e));
                } finally {
                    work.end();
                }
            });
        } catch (RejectedExecutionException e) {
            work.end();
            LOG.debug("background work '{}' of {} refused: the engine is stopping", what, id);
        }
    }

    // ------------------------------------------------------------------ status

    ObjectNode status(long nowMicros) {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("id", id);
        n.put("type", type);
        n.put("layer", method.layer().configName());
        n.put("state", lifecycle.state().name());
        if (!lifecycle.failure().isEmpty()) {
            n.put("failure", lifecycle.failure());
        }
        n.put("ready", ready);
        if (!readinessDetail.isEmpty()) {
            n.put("readiness", readinessDetail);
        }
        n.put("stale", stale);
        scheduler.host().status(n);
        scheduler.statusTo(n, nowMicros);
        ObjectNode inputs = n.putObject("inputs");
        for (InputSlot slot : slots) {
            ObjectNode i = inputs.putObject(slot.input().name());
            i.put("delivery", slot.delivery().mode().name().toLowerCase(java.util.Locale.ROOT));
            i.put("depth", slot.depth());
            i.put("offered", slot.offered());
            i.put("dropped", slot.dropped());
            i.put("conflated", slot.conflated());
        }
        ObjectNode outputs = n.putObject("outputs");
        for (Output<?> out : method.outputs()) {
            outputs.put(out.name(), ports.get(out).published());
        }
        return n;
    }
}
