package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.LockSupport;
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
 * own thread, a slow method (speech, vision) never holds up a light one.
 */
final class MethodRunner implements MethodContext {

    private static final Logger LOG = LoggerFactory.getLogger(MethodRunner.class);
    private static final long IDLE_PARK_NANOS = TimeUnit.MILLISECONDS.toNanos(100);

    private final String id;
    private final String type;
    private final Method method;
    private final MethodLifecycle lifecycle;
    private final EngineClock clock;
    private final ExecutorService backgroundPool;
    private final List<InputSlot> slots = new ArrayList<>();
    /** The input slots and output ports by their port's declaration index ({@link Input#index()}). */
    private final InputSlot[] slotByInput;
    private final OutputPort[] ports;
    private final Map<Input<?>, ChannelDescriptor> channels = new HashMap<>();
    private final Map<Output<?>, ChannelDescriptor> commandChannels = new HashMap<>();
    private final ConcurrentLinkedQueue<Runnable> turns = new ConcurrentLinkedQueue<>();
    /**
     * Whether the method's thread is about to park or parked: set before it looks at its slots one last time,
     * so a producer that finds it false knows the thread will see its sample, and unparks only a thread that
     * may sleep (an unpark costs a lock and, for a sleeping thread, a system call).
     */
    private volatile boolean parking;
    private final AtomicBoolean tickPending = new AtomicBoolean();
    private final RateMeter handled = new RateMeter();
    private final LatencyStats latency = new LatencyStats();
    private volatile boolean running;
    private volatile boolean stale;
    private volatile boolean ready = true;
    private volatile String readinessDetail = "";
    private AutoCloseable ticker;
    private Thread thread;
    private final MethodHost.Local local;
    private volatile MethodHost host;
    private volatile Consumer<ControlNotice> controlNotices = n -> { };
    private LongSupplier motionResets;
    private long motionResetsSeen;

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
        }
        slotByInput = slots.toArray(InputSlot[]::new);
        ports = new OutputPort[method.outputs().size()];
        for (Output<?> out : method.outputs()) {
            ports[out.index()] = new OutputPort(id + "." + out.name());
        }
        lifecycle = MethodLifecycle.attach(method, this);
        local = new MethodHost.Local(lifecycle, () -> method.tickPeriod()
                .ifPresent(p -> ticker = clock.every(p.toNanos() / 1_000, this::requestTick)));
        host = local;
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

    /** The slot of one of this method's inputs; null for another method's input. */
    InputSlot slot(Input<?> input) {
        int i = input.index();
        return i >= 0 && i < slotByInput.length && slotByInput[i].input() == input ? slotByInput[i] : null;
    }

    /** The port of one of this method's outputs (the method checked that it is one of its own). */
    OutputPort port(Output<?> output) {
        return ports[output.index()];
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
        this.motionResets = resets;
        this.motionResetsSeen = resets.getAsLong();
    }

    /**
     * Runs the method on a worker: from now on its input samples go to {@code remote} instead of the method
     * object here, which runs only as the fallback while the worker is lost (if the config asks for one).
     * Call before {@link #start}.
     */
    void placeOn(RemotePlacement remote) {
        this.host = new MethodHost.OnWorker(id, remote, local);
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
        running = true;
        thread = new Thread(this::loop, "habla-method-" + id);
        thread.setDaemon(true);
        host.start();
        thread.start();
    }

    /** From the placement, on any thread: the worker was lost and the fallback is to run here. */
    void fallBackToLocal() {
        addTurn(() -> {
            if (host instanceof MethodHost.OnWorker w) {
                w.fallBack();
            }
        });
        wake();
    }

    /** Stops the thread, then the method. Waits at most {@code waitMillis} for the current turn. */
    void stop(long waitMillis) {
        running = false;
        closeTicker();
        if (thread != null) {
            LockSupport.unpark(thread);
            try {
                thread.join(waitMillis);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            if (thread.isAlive()) {
                LOG.warn("method {} is still busy after {} ms; stopping it anyway", id, waitMillis);
            }
        }
        host.stop();
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
            addTurn(() -> {
                tickPending.set(false);
                tap.periodic(TICK_PREFIX + id, clock.nowMicros(), consumed());
                host.tick(clock.nowMicros());
            });
            wake();
        }
    }

    private void addTurn(Runnable turn) {
        work.begin();
        turns.add(turn);
    }

    private void wake() {
        if (parking) {
            Thread t = thread;
            if (t != null) {
                LockSupport.unpark(t);
            }
        }
    }

    private void loop() {
        while (running) {
            if (!drainOnce()) {
                // Say so before the last look: a sample offered after it finds parking set and unparks us.
                parking = true;
                if (running && nothingWaiting()) {
                    LockSupport.parkNanos(this, IDLE_PARK_NANOS);
                }
                parking = false;
            }
        }
    }

    private boolean nothingWaiting() {
        for (InputSlot slot : slots) {
            if (!slot.isEmpty()) {
                return false;
            }
        }
        return turns.isEmpty();
    }

    /** One pass: at most one sample from every input (round robin), then the turns waiting now. */
    private boolean drainOnce() {
        boolean worked = false;
        for (InputSlot slot : slots) {
            Sample s = slot.poll();
            if (s != null) {
                worked = true;
                catchUpMotionReset();
                long now = clock.nowMicros();
                latency.record(now - s.sourceMicros());
                handled.mark(now);
                try {
                    route(slot.input(), s);
                } finally {
                    work.end();
                }
            }
        }
        for (int n = turns.size(); n > 0; n--) {
            Runnable turn = turns.poll();
            if (turn == null) {
                break;
            }
            worked = true;
            catchUpMotionReset();
            try {
                turn.run();
            } finally {
                work.end();
            }
        }
        return worked;
    }

    /**
     * Tells the method of a motion reset it has not heard of yet. Read after the message was taken, so a message
     * that came after a reset (a value written once control is back) always finds the reset told first.
     */
    private void catchUpMotionReset() {
        LongSupplier resets = motionResets;
        if (resets == null) {
            return;
        }
        long now = resets.getAsLong();
        if (now != motionResetsSeen) {
            motionResetsSeen = now;
            host.motionStopped();
        }
    }

    /** Hands a sample to where the method runs. */
    private void route(Input<?> input, Sample s) {
        host.deliver(input, s);
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
        ports[output.index()].publish(value, sourceMicros, stale);
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
                    addTurn(() -> lifecycle.runTurn(what, () -> done.accept(result)));
                } catch (Exception | LinkageError e) {
                    addTurn(() -> lifecycle.fail(what, e));
                } finally {
                    work.end();
                }
                wake();
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
        host.status(n);
        n.put("handled", handled.total());
        n.put("handledPerS", handled.perSecond(nowMicros));
        n.set("latency", latency.snapshot());
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
            outputs.put(out.name(), ports[out.index()].published());
        }
        return n;
    }
}
