package org.habla.method;

import java.util.Objects;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;

/**
 * An output of one method: its {@link OutputPort}, bound in the method's constructor through
 * {@code Method.output(port)}; the method emits its values through it. The shape tells control clients what
 * the values look like (it goes in the socket's hello line).
 */
public final class Output<P extends Payload> {

    private final OutputPort<P> port;
    private int index = -1;

    Output(OutputPort<P> port) {
        this.port = Objects.requireNonNull(port, "port");
    }

    /** What the output is: name, type, shape. */
    public OutputPort<P> port() {
        return port;
    }

    public String name() {
        return port.name();
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
        return port.type();
    }

    public PayloadKind kind() {
        return port.kind();
    }

    public Shape shape() {
        return port.shape();
    }

    @Override
    public String toString() {
        return "output " + port.name() + " (" + kind().wireName() + ")";
    }
}
