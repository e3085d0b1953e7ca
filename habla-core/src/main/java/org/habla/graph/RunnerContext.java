package org.habla.graph;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.function.Consumer;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.ControlNotice;
import org.habla.method.Input;
import org.habla.method.Method;
import org.habla.method.MethodContext;
import org.habla.method.MethodLifecycle;
import org.habla.method.Output;
import org.habla.sample.Payload;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What a method running in the daemon sees of the engine: its id and the engine's clock, its output ports (each
 * sample carries whether the method is stale now), the interface channels its ports are wired to, its readiness,
 * its notices to control clients, and background work whose outcome comes back as a turn on the method's thread.
 */
final class RunnerContext implements MethodContext {

    private static final Logger LOG = LoggerFactory.getLogger(RunnerContext.class);

    /** Where a background task's outcome goes: a turn on the method's thread. */
    interface Turns {
        /** The task's result, to be handed to the method in a turn of its own. */
        void done(String what, MethodLifecycle.ThrowingRunnable result);

        /** The task threw: the method fails, in a turn of its own. */
        void failed(String what, Throwable cause);
    }

    /**
     * The pool of a method of a light type: it refuses every task, since a light method runs on the thread that
     * delivers to it and a background result would come back on a thread of the pool's.
     */
    static final Executor NO_BACKGROUND = task -> {
        throw new IllegalStateException("a method of a light type runs no background work (its type must not be"
                + " declared light)");
    };

    private final String id;
    private final EngineClock clock;
    private final Executor backgroundPool;
    private final WorkCount work;
    private final Turns turns;
    /** The output ports by their output's declaration index ({@link Output#index()}). */
    private final Producer[] ports;
    private final Map<Input<?>, ChannelDescriptor> channels = new HashMap<>();
    private final Map<Output<?>, ChannelDescriptor> commandChannels = new HashMap<>();
    private volatile boolean stale;
    private volatile StaleCause staleCause;
    private volatile boolean ready = true;
    private volatile String readinessDetail = "";
    private volatile Consumer<ControlNotice> controlNotices = n -> { };

    RunnerContext(String id, Method method, EngineClock clock, Executor backgroundPool, WorkCount work,
            Turns turns) {
        this.id = id;
        this.clock = clock;
        this.backgroundPool = backgroundPool;
        this.work = work;
        this.turns = turns;
        ports = new Producer[method.outputs().size()];
        for (Output<?> out : method.outputs()) {
            ports[out.index()] = new Producer(id + "." + out.name());
        }
    }

    Producer port(Output<?> output) {
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
        Map<String, ChannelDescriptor> m = new LinkedHashMap<>();
        channels.forEach((in, c) -> m.put(in.name(), c));
        return m;
    }

    /** The interface channels the outputs write, by output name (for a worker running the method). */
    Map<String, ChannelDescriptor> commandChannelsByOutput() {
        Map<String, ChannelDescriptor> m = new LinkedHashMap<>();
        commandChannels.forEach((out, c) -> m.put(out.name(), c));
        return m;
    }

    /** Marks the outputs stale for {@code cause}, or fresh when it is null. */
    void stale(StaleCause cause) {
        staleCause = cause;
        stale = cause != null;
    }

    /** Adds whether the outputs are stale, and why ({@code staleBecause}), to a method's status. */
    void staleTo(com.fasterxml.jackson.databind.node.ObjectNode status) {
        StaleCause cause = staleCause;
        status.put("stale", cause != null);
        if (cause != null) {
            status.putObject("staleBecause").put("source", cause.source()).put("why", cause.why());
        }
    }

    @Override
    public boolean stale() {
        return stale;
    }

    /** Sets the readiness before the method runs, without telling the log (a method waiting for its worker). */
    void startNotReady(String detail) {
        ready = false;
        readinessDetail = detail;
    }

    boolean ready() {
        return ready;
    }

    String readinessDetail() {
        return readinessDetail;
    }

    /** Where the method's notices to control clients go (the exposed methods whose values reach it). */
    void tellControlVia(Consumer<ControlNotice> sink) {
        controlNotices = sink;
    }

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
                    turns.done(what, () -> done.accept(result));
                } catch (Exception | LinkageError e) {
                    turns.failed(what, e);
                } finally {
                    work.end();
                }
            });
        } catch (RejectedExecutionException e) {
            work.end();
            LOG.debug("background work '{}' of {} refused: the engine is stopping", what, id);
        } catch (RuntimeException e) {
            work.end();
            throw e; // a light method's: it fails, saying why
        }
    }
}
