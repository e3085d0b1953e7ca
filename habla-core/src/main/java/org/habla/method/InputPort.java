package org.habla.method;

import java.util.Objects;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;

/**
 * What an input of a method type is: its name, payload type, delivery and whether a config may leave it
 * unwired. A method class declares each once, as a constant, lists it in its type's {@link Ports} and binds
 * it in its constructor with {@code Method.input(port, handler)}; so a config is checked against the ports
 * without making the method, and the port a method binds is the one its type lists.
 *
 * @param name     the name the config wires ({@code "scan"})
 * @param type     the payload type the input takes
 * @param delivery how samples wait for the method
 * @param optional whether a config may leave the input unwired
 */
public record InputPort<P extends Payload>(String name, Class<P> type, Delivery delivery, boolean optional)
        implements Ports.Port {

    public InputPort {
        PortNames.check(name);
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(delivery, "delivery");
    }

    /** An input with {@code latest} delivery. */
    public static <P extends Payload> InputPort<P> of(String name, Class<P> type) {
        return new InputPort<>(name, type, Delivery.latest(), false);
    }

    public static <P extends Payload> InputPort<P> of(String name, Class<P> type, Delivery delivery) {
        return new InputPort<>(name, type, delivery, false);
    }

    /** An input the config may leave unwired. */
    public static <P extends Payload> InputPort<P> optional(String name, Class<P> type, Delivery delivery) {
        return new InputPort<>(name, type, delivery, true);
    }

    public PayloadKind kind() {
        return PayloadKind.of(type);
    }

    @Override
    public String toString() {
        return (optional ? "optional " : "") + "input " + name + " (" + kind().wireName() + ", "
                + delivery.mode().name().toLowerCase(java.util.Locale.ROOT)
                + (delivery.mode() == Delivery.Mode.QUEUE ? " " + delivery.capacity() : "") + ")";
    }
}
