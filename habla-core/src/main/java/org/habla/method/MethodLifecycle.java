package org.habla.method;

import java.util.Objects;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The engine's side of one method: its life cycle {@code NEW → ATTACHED → RUNNING → STOPPED} (or {@code FAILED})
 * and the calls that move it. A method author never sees it — a {@link Method} declares ports and fills hooks, and
 * whatever hosts the method (the daemon's runner, a worker, {@link MethodHarness} in a test) attaches it once and
 * drives it from here. Every transition is checked; an exception thrown by a hook puts the method in
 * {@code FAILED} with one log line, and a failed method is handed nothing more.
 */
public final class MethodLifecycle {

    private static final Logger LOG = LoggerFactory.getLogger(Method.class);

    private final Method method;
    private final MethodContext context;
    private volatile MethodState state = MethodState.ATTACHED;
    private volatile String failure = "";
    private volatile Throwable failureCause;

    private MethodLifecycle(Method method, MethodContext context) {
        this.method = method;
        this.context = context;
    }

    /**
     * Gives {@code method} its context: NEW → ATTACHED.
     *
     * @throws IllegalStateException if the method was attached before (a method is hosted once)
     */
    public static MethodLifecycle attach(Method method, MethodContext context) {
        Objects.requireNonNull(context, "context");
        synchronized (method) {
            if (method.lifecycle != null) {
                throw new IllegalStateException("cannot attach in state " + method.lifecycle.state + " (needs NEW)");
            }
            MethodLifecycle l = new MethodLifecycle(method, context);
            method.lifecycle = l;
            return l;
        }
    }

    /** {@code NEW} for a method no engine has attached yet, else the state of its life cycle. */
    public static MethodState stateOf(Method method) {
        MethodLifecycle l = method.lifecycle;
        return l == null ? MethodState.NEW : l.state;
    }

    public Method method() {
        return method;
    }

    MethodContext context() {
        return context;
    }

    public MethodState state() {
        return state;
    }

    /** Why the method failed, or an empty string. */
    public String failure() {
        return failure;
    }

    /** ATTACHED → RUNNING, or FAILED if {@link Method#onStart} throws. */
    public void start() {
        requireState(MethodState.ATTACHED, "start");
        method.currentSourceMicros = context.nowMicros();
        state = MethodState.RUNNING;
        guard("start", method::onStart);
    }

    /** Hands one sample of one input to the method, if it is running. */
    public void deliver(Input<?> input, Sample sample) {
        if (state != MethodState.RUNNING) {
            return;
        }
        method.currentSourceMicros = sample.sourceMicros();
        try {
            dispatch(input, sample); // not through guard: no words are made for a sample that is handled
        } catch (Exception | LinkageError | AssertionError e) {
            markFailed("handle a sample of " + input.name(), e);
        }
    }

    /** A tick, if the method is running. */
    public void tick(long nowMicros) {
        if (state != MethodState.RUNNING) {
            return;
        }
        method.currentSourceMicros = nowMicros;
        guard("tick", () -> method.onTick(nowMicros));
    }

    /** The robot was stopped by the engine (or control came back after that), if the method is running. */
    public void motionStopped() {
        if (state != MethodState.RUNNING) {
            return;
        }
        method.currentSourceMicros = context.nowMicros();
        guard("forget its motion after a motion stop", method::onMotionStopped);
    }

    /** Runs a piece of method code (a background result) as a turn, if the method is running. */
    public void runTurn(String what, ThrowingRunnable turn) {
        if (state != MethodState.RUNNING) {
            return;
        }
        method.currentSourceMicros = context.nowMicros();
        guard(what, turn);
    }

    /** What the method threw when it failed, or null. */
    public Throwable failureCause() {
        return failureCause;
    }

    /** A failure that happened on the method's behalf (e.g. its background task). */
    public void fail(String what, Throwable cause) {
        if (state == MethodState.RUNNING || state == MethodState.ATTACHED) {
            markFailed(what, cause);
        }
    }

    /** RUNNING or FAILED → STOPPED (FAILED stays FAILED); calls {@link Method#onStop} once. */
    public void stop() {
        MethodState was = state;
        if (was == MethodState.STOPPED) {
            return;
        }
        if (was == MethodState.RUNNING) {
            state = MethodState.STOPPED;
        }
        try {
            method.onStop();
        } catch (Exception e) {
            LOG.warn("method {} failed to stop cleanly: {}", method.id(), e.toString());
        }
    }

    @SuppressWarnings({"unchecked", "rawtypes"})
    private void dispatch(Input<?> input, Sample sample) throws Exception {
        InputHandler handler = input.handler();
        if (handler == null) {
            method.onSample(input, sample);
        } else {
            handler.handle(input.payload(sample), sample);
        }
    }

    private void guard(String what, ThrowingRunnable body) {
        try {
            body.run();
        } catch (Exception | LinkageError | AssertionError e) {
            markFailed(what, e);
        }
    }

    private void markFailed(String what, Throwable e) {
        failure = "failed to " + what + ": " + e;   // before the state, so whoever sees FAILED sees why
        failureCause = e;
        state = MethodState.FAILED;
        LOG.error("method {} ({}) FAILED to {}: {}", method.id(), method.getClass().getSimpleName(), what, e.toString());
        LOG.debug("method {} failure trace", method.id(), e);
    }

    /** A piece of method code that may throw: a hook, a background result. */
    @FunctionalInterface
    public interface ThrowingRunnable {
        void run() throws Exception;
    }

    private void requireState(MethodState expected, String action) {
        if (state != expected) {
            throw new IllegalStateException("cannot " + action + " in state " + state + " (needs " + expected + ")");
        }
    }
}
