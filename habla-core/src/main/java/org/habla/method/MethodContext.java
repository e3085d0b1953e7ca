package org.habla.method;

import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.function.Consumer;
import org.habla.driver.ChannelDescriptor;
import org.habla.sample.Payload;

/**
 * What the engine (or the test harness) offers a method: its identity, the clock, a way out for
 * its outputs and a way to run slow work off the method's own turn. Methods reach it through the
 * protected helpers of {@link Method}; they never hold on to it themselves.
 */
public interface MethodContext {

    /** The method's id in the config. */
    String methodId();

    /** The engine's clock, in microseconds since the epoch. */
    long nowMicros();

    /** Publishes a value on an output, stamped with the time of the raw reading it derives from. */
    void emit(Output<?> output, Payload value, long sourceMicros);

    /** The descriptor of the interface channel an input is wired to, if it is wired to one. */
    Optional<ChannelDescriptor> channelOf(Input<?> input);

    /** The descriptor of the interface command channel an output writes, if it writes one. */
    default Optional<ChannelDescriptor> commandChannelOf(Output<?> output) {
        return Optional.empty();
    }

    /**
     * Tells the control clients whose values reach this method something about what they asked (see
     * {@link ControlNotice}); nothing where no control socket reaches it, or where the method runs on a worker.
     */
    default void tellControl(ControlNotice notice) {
    }

    /**
     * Whether something the method's inputs come from is down now (a link, a device its driver says is unavailable,
     * a worker): what it emits meanwhile is marked stale, and a command it sends there may be dropped on the way.
     */
    default boolean stale() {
        return false;
    }

    /** Tells the status whether the method can do its work yet (e.g. a model still loading). */
    void readiness(boolean ready, String detail);

    /**
     * Runs {@code task} away from the method's turn (on the engine's pool for slow work) and hands
     * its result to {@code done} later, as an ordinary turn of the method: method code stays single
     * threaded. If the task throws, the method fails.
     */
    <T> void background(String what, Callable<T> task, Consumer<T> done);
}
