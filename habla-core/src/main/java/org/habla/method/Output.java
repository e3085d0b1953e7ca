package org.habla.method;

import java.util.Objects;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;

/**
 * A named, typed output of a method, declared once as a field through {@code Method.output(..)}.
 * The shape tells control clients what the values look like (it goes in the socket's hello line).
 */
public final class Output<P extends Payload> {

    private final String name;
    private final Class<P> type;
    private final Shape shape;
    private int index = -1;

    Output(String name, Class<P> type, Shape shape) {
        this.name = PortNames.check(name);
        this.type = Objects.requireNonNull(type, "type");
        this.shape = Objects.requireNonNull(shape, "shape");
        if (!shape.kind().accepts(PayloadKind.of(type))) {
            throw new IllegalArgumentException("output " + name + ": shape kind " + shape.kind()
                    + " does not match type " + type.getSimpleName());
        }
    }

    public String name() {
        return name;
    }

    /**
     * Where the output stands among its method's outputs, in the order they were declared (0 first): the
     * engine keeps a method's output ports in an array by this index, so an emitted value finds its port
     * without a map look-up.
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

    public Shape shape() {
        return shape;
    }

    @Override
    public String toString() {
        return "output " + name + " (" + kind().wireName() + ")";
    }
}
