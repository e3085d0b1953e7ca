package org.habla.method;

import java.util.Objects;
import java.util.Optional;
import java.util.function.Function;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;
import org.habla.sample.Sample;

/**
 * A named, typed input of a method. Declared once, as a field, through {@code Method.input(..)};
 * the config wires it to an output of another method, to a channel of an interface or to the
 * method's control socket.
 */
public final class Input<P extends Payload> {

    private final String name;
    private final Class<P> type;
    private final Delivery delivery;
    private final InputHandler<P> handler;
    private final boolean optional;
    private final Function<? super P, String> refusal;
    private int index = -1;

    Input(String name, Class<P> type, Delivery delivery, InputHandler<P> handler, boolean optional) {
        this(name, type, delivery, handler, optional, null);
    }

    Input(String name, Class<P> type, Delivery delivery, InputHandler<P> handler, boolean optional,
            Function<? super P, String> refusal) {
        this.name = PortNames.check(name);
        this.type = Objects.requireNonNull(type, "type");
        this.delivery = Objects.requireNonNull(delivery, "delivery");
        this.handler = handler;
        this.optional = optional;
        this.refusal = refusal;
    }

    public String name() {
        return name;
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
        return type;
    }

    public PayloadKind kind() {
        return PayloadKind.of(type);
    }

    public Delivery delivery() {
        return delivery;
    }

    /** Whether a config may leave this input unwired. */
    public boolean optional() {
        return optional;
    }

    /** The sample's payload as this input's type. */
    public P payload(Sample sample) {
        return type.cast(sample.payload());
    }

    /** Whether {@code payload} fits this input. */
    public boolean accepts(Payload payload) {
        return type.isInstance(payload);
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
        return Optional.ofNullable(refusal.apply(type.cast(payload)));
    }

    InputHandler<P> handler() {
        return handler;
    }

    @Override
    public String toString() {
        return "input " + name + " (" + kind().wireName() + ")";
    }
}
