package org.habla.method;

import java.util.Objects;
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

    Input(String name, Class<P> type, Delivery delivery, InputHandler<P> handler, boolean optional) {
        this.name = PortNames.check(name);
        this.type = Objects.requireNonNull(type, "type");
        this.delivery = Objects.requireNonNull(delivery, "delivery");
        this.handler = handler;
        this.optional = optional;
    }

    public String name() {
        return name;
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

    InputHandler<P> handler() {
        return handler;
    }

    @Override
    public String toString() {
        return "input " + name + " (" + kind().wireName() + ")";
    }
}
