package org.habla.net;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.habla.method.ControlNotice;
import org.habla.method.Input;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.Shape;
import org.habla.sample.Payload;
import org.habla.sample.Sample;

/**
 * What the engine shows a control server of one exposed method: its description for the hello line,
 * its output samples, and a way to write values to its control inputs. The server knows nothing
 * else of the graph.
 */
public interface ControlPoint {

    /** The socket's name in the control contract. */
    String name();

    String methodId();

    Layer layer();

    /** Outputs whose samples stream to clients. */
    List<Output<?>> outputs();

    /** What an output's values look like with what feeds it (a hand-on output shows its source's shape). */
    default Shape shapeOf(Output<?> output) {
        return output.shape();
    }

    /** Inputs wired to {@code control}: clients write values to these. */
    List<Input<?>> controlInputs();

    /** The newest sample of every output that has emitted one. */
    Map<String, Sample> latest();

    /** Whether a hardware link the method depends on is down. */
    boolean stale();

    /**
     * Registers a listener for every sample the method emits and every change of staleness.
     * The listener is called on engine threads and must not block.
     */
    Subscription subscribe(Listener listener);

    /**
     * Hands a client's value to a control input. Never blocks.
     *
     * @throws Rejected if the value cannot be taken (e.g. the input's queue is full, the method failed)
     */
    void write(Input<?> input, Payload value) throws Rejected;

    /** Tells the engine the client that commanded this socket went away or gave control back: stop the robot. */
    void writerLeft();

    /**
     * Who commands this socket, when values written here can reach a robot's command channel: such a socket has
     * one commander at a time, whatever the writes come through (its control socket, a bridge), and writing to it
     * counts for the motion watchdog. Empty for a socket whose values move nothing.
     */
    default Optional<ControlLease> lease() {
        return Optional.empty();
    }

    /** Receives what an exposed method emits. */
    interface Listener {
        void onSample(Output<?> output, Sample sample);

        void onStale(boolean stale, String why);

        /** A method the socket's values reach tells its clients something about what they asked. */
        default void onNotice(ControlNotice notice) {
        }

        /** Who commands the socket changed: a {@code control} line for every client (see {@link ControlLease}). */
        default void onControl(Frame line) {
        }
    }

    /** Ends a subscription. */
    interface Subscription extends AutoCloseable {
        @Override
        void close();
    }

    /** A value the engine would not take, with a wire error code. */
    final class Rejected extends Exception {
        private static final long serialVersionUID = 1L;
        private final String code;

        public Rejected(String code, String message) {
            super(message, null, false, false); // an answer to a client, not a fault: no stack trace to fill in
            this.code = code;
        }

        public String code() {
            return code;
        }
    }
}
