package org.habla.graph;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.ControlNotice;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.Method;
import org.habla.method.MethodLifecycle;
import org.habla.method.MethodState;
import org.habla.method.Output;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs one method: takes samples from its input slots, ticks and background results, and hands them to the method
 * one at a time, on a thread of its own or on the thread that delivers to it, as the graph's {@link ThreadPlan}
 * chose. A heavy method (speech, vision) has its own thread, so it never holds up a light one. The thread and the
 * order of messages are its {@link MethodScheduler}'s, what the method sees of the engine its
 * {@link RunnerContext}'s; the runner puts them together, ticks the method, and says in the status how it is doing.
 */
final class MethodRunner {

    private static final Logger LOG = LoggerFactory.getLogger(MethodRunner.class);

    private final String id;
    private final String type;
    private final Method method;
    private final MethodLifecycle lifecycle;
    private final EngineClock clock;
    private final List<InputSlot> slots = new ArrayList<>();
    /** The input slots by their input's declaration index ({@link Input#index()}). */
    private final InputSlot[] slotByInput;
    private final AtomicBoolean tickPending = new AtomicBoolean();
    private AutoCloseable ticker;
    private final MethodHost.Local local;
    private final RunnerContext context;
    private final MethodScheduler scheduler;

    static final String TICK_PREFIX = "tick:";
    private final GraphTap tap;

    /** A runner with a thread of its own (a method hosted for a daemon, on a worker). */
    MethodRunner(String id, String type, Method method, EngineClock clock, ExecutorService backgroundPool,
            WorkCount work, GraphTap tap) {
        this(id, type, method, clock, backgroundPool, work, tap, java.util.Set.of(),
                ThreadPlan.Choice.own(id, false, "it is hosted alone"));
    }

    /**
     * A runner whose inputs named in {@code latestInputs} (the wires of a declared cycle) hold only the newest
     * sample, whatever delivery the method type asks for, and whose messages run where {@code thread} says: on a
     * thread of its own, or on the thread that delivers to it.
     */
    MethodRunner(String id, String type, Method method, EngineClock clock, ExecutorService backgroundPool,
            WorkCount work, GraphTap tap, java.util.Set<String> latestInputs, ThreadPlan.Choice thread) {
        this.tap = tap;
        this.id = id;
        this.type = type;
        this.method = method;
        this.clock = clock;
        for (Input<?> in : method.inputs()) {
            String input = in.name();
            slots.add(new InputSlot(in, latestInputs.contains(input) ? Delivery.latest() : in.delivery(), taker,
                    work, arrival -> tap.skipped(id, input, arrival)));
        }
        slotByInput = slots.toArray(InputSlot[]::new);
        context = new RunnerContext(id, method, clock, thread.light() ? RunnerContext.NO_BACKGROUND : backgroundPool,
                work, new RunnerContext.Turns() {
            @Override
            public void done(String what, MethodLifecycle.ThrowingRunnable result) {
                scheduler.turn(() -> lifecycle.runTurn(what, result));
            }

            @Override
            public void failed(String what, Throwable cause) {
                scheduler.turn(() -> lifecycle.fail(what, cause));
            }
        });
        lifecycle = MethodLifecycle.attach(method, context);
        local = new MethodHost.Local(lifecycle, () -> method.tickPeriod()
                .ifPresent(p -> ticker = clock.every(p.toNanos() / 1_000, this::requestTick)));
        scheduler = thread.inline()
                ? new InlineScheduler(id, slots, clock, work, local, thread.thread(), thread.reason())
                : new OwnThreadScheduler(id, slots, clock, work, local, thread.reason());
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
    Producer port(Output<?> output) {
        return context.port(output);
    }

    void bindChannel(Input<?> input, ChannelDescriptor channel) {
        context.bindChannel(input, channel);
    }

    void bindCommandChannel(Output<?> output, ChannelDescriptor channel) {
        context.bindCommandChannel(output, channel);
    }

    /** Marks the outputs stale for {@code cause}, or fresh when it is null. */
    void stale(StaleCause cause) {
        context.stale(cause);
    }

    boolean stale() {
        return context.stale();
    }

    /**
     * Makes the method hear of motion resets ({@link MotionWatchdog}): before it handles anything that comes
     * after one, it is told the robot was stopped. For methods whose outputs lead to a motion channel; call
     * before {@link #start}.
     */
    void followMotionResets(LongSupplier resets) {
        scheduler.followMotionResets(resets);
    }

    /** Whether the method runs on the thread that delivers to it. */
    boolean inline() {
        return scheduler instanceof InlineScheduler;
    }

    /** What the method sees of the engine: its ports, channels, readiness. */
    RunnerContext context() {
        return context;
    }

    /** The method object in this daemon, as a host. */
    MethodHost.Local local() {
        return local;
    }

    /** Where the method runs now: in the daemon unless it was moved ({@link #runOn}). */
    MethodHost host() {
        return scheduler.host();
    }

    /** Has the method run on {@code host} instead of here (a worker's placement); before {@link #start}. */
    void runOn(MethodHost host) {
        scheduler.host(host);
    }

    /** Runs {@code turn} on the method's thread, between its messages. From any thread. */
    void turn(Runnable turn) {
        scheduler.turn(turn);
    }

    boolean ready() {
        return context.ready();
    }

    String readinessDetail() {
        return context.readinessDetail();
    }

    long nowMicros() {
        return clock.nowMicros();
    }

    /** Where the method's notices to control clients go (the exposed methods whose values reach it). */
    void tellControlVia(Consumer<ControlNotice> sink) {
        context.tellControlVia(sink);
    }

    /** Starts the method and its thread; a method placed on a worker starts here only when it must run locally. */
    void start() {
        scheduler.start();
    }

    /** What the slots hand their samples to: the scheduler, made after them. */
    private final InputSlot.Taker taker = new InputSlot.Taker() {
        @Override
        public void wake() {
            scheduler.wake();
        }

        @Override
        public boolean takeNow(InputSlot slot, Sample sample, long arrival) {
            return scheduler.takeNow(slot, sample, arrival);
        }
    };

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

    ObjectNode status(long nowMicros) {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("id", id);
        n.put("type", type);
        n.put("layer", method.layer().configName());
        n.put("state", lifecycle.state().name());
        if (!lifecycle.failure().isEmpty()) {
            n.put("failure", lifecycle.failure());
        }
        n.put("ready", context.ready());
        if (!context.readinessDetail().isEmpty()) {
            n.put("readiness", context.readinessDetail());
        }
        context.staleTo(n);
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
            outputs.put(out.name(), context.port(out).published());
        }
        return n;
    }
}
