package org.habla.method.builtin;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.Shape;
import org.habla.sample.Payload;
import org.habla.sample.PayloadKind;

/**
 * The two ports of a relay ({@code pass-through}, {@code channel}): input {@code in}, output {@code out}, one type.
 * The output hands on what the input receives, so it shows the shape of whatever feeds {@code in}.
 */
record RelayPorts<P extends Payload>(InputPort<P> in, OutputPort<P> out) {

    static RelayPorts<?> of(RelayParams params) {
        return of(params.payloadKind().type(), params.inputDelivery());
    }

    private static <P extends Payload> RelayPorts<P> of(Class<P> type, Delivery delivery) {
        return new RelayPorts<>(InputPort.of("in", type, delivery),
                OutputPort.of("out", type, Shape.passedOn(PayloadKind.of(type), "in")));
    }

    static Ports ports(RelayParams params) {
        RelayPorts<?> r = of(params);
        return Ports.of(r.in(), r.out());
    }
}
