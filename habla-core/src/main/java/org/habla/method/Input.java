package org.habla.method;

import java.util.Objects;
import java.util.Optional;
import java.util.function.Function;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;
import org.habla.sample.Sample;

/**
 * An input of one method: its {@link InputPort}, bound in the method's constructor through
 * {@code Method.input(port, ..)} with the handler that takes its samples. The config wires it to an
 * output of another method, to a channel of an interface or to the method's control socket.
 */
public final class Input<P extends Payload> {

    private final InputPort<P> port;
    private final InputHandler<P> handler;
    private final Function<? super P, String> refusal;
    private int index = -1;

    Input(InputPort<P> port, InputHandler<P> handler, Function<? super P, String> refusal) {
        this.port = Objects.requireNonNull(port, "port");
        this.handler = handler;
        this.refusal = refusal;
    }

    /** What the input is: name, type, delivery, whether optional. */
    public InputPort<P> port() {
        return port;
    }

    public String name() {
        return port.name();
    }

    /**
     * Where the input stands among its method's inputs, in the order they were declared (0 first): the
     * engine keeps a method's input queues in an array by this index, so a sample finds its queue without
     * a map look-up.
     */
    public int index() {
        return index;
    }

    void declaredAt(int position) {
        index = position;
    }

    public Class<P> type() {
        return port.type();
    }

    public PayloadKind kind() {
        return port.kind();
    }

    public Delivery delivery() {
        return port.delivery();
    }

    /** Whether a config may leave this input unwired. */
    public boolean optional() {
        return port.optional();
    }

    /** The sample's payload as this input's type. */
    public P payload(Sample sample) {
        return port.type().cast(sample.payload());
    }

    /** Whether {@code payload} fits this input. */
    public boolean accepts(Payload payload) {
        return port.type().isInstance(payload);
    }

    /**
     * Why the method would refuse {@code payload} written by a control client, or empty if it takes it.
     * The engine asks before it queues a control write, so the client gets an error line at once
     * instead of a value that silently does nothing. Only a payload this input {@link #accepts} is checked.
     */
    public Optional<String> refusal(Payload payload) {
        if (refusal == null || !accepts(payload)) {
            return Optional.empty();
        }
        return Optional.ofNullable(refusal.apply(port.type().cast(payload)));
    }

    InputHandler<P> handler() {
        return handler;
    }

    @Override
    public String toString() {
        return "input " + port.name() + " (" + kind().wireName() + ")";
    }
}
