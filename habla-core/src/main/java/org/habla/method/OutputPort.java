package org.habla.method;

import java.util.Objects;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;

/**
 * What an output of a method type is: its name, payload type and the shape that tells clients what its
 * values look like. Declared once per method class, as a constant, listed in its type's {@link Ports} and
 * bound in the constructor with {@code Method.output(port)}.
 *
 * @param name  the name the config and clients use ({@code "nearest"})
 * @param type  the payload type of its values
 * @param shape unit, fields and meaning (it goes in the socket's hello line)
 */
public record OutputPort<P extends Payload>(String name, Class<P> type, Shape shape) implements Ports.Port {

    public OutputPort {
        PortNames.check(name);
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(shape, "shape");
        if (!shape.kind().accepts(PayloadKind.of(type))) {
            throw new IllegalArgumentException("output " + name + ": shape kind " + shape.kind()
                    + " does not match type " + type.getSimpleName());
        }
    }

    /** An output whose shape is just its kind. */
    public static <P extends Payload> OutputPort<P> of(String name, Class<P> type) {
        return new OutputPort<>(name, type, Shape.of(PayloadKind.of(type)));
    }

    public static <P extends Payload> OutputPort<P> of(String name, Class<P> type, Shape shape) {
        return new OutputPort<>(name, type, shape);
    }

    public PayloadKind kind() {
        return PayloadKind.of(type);
    }

    @Override
    public String toString() {
        return "output " + name + " (" + kind().wireName() + ")";
    }
}
