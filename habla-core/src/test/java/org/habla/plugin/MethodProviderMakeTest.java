package org.habla.plugin;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.sample.NumberValue;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

/** The engine makes a method only as its type lists it: a method that binds other ports is refused. */
class MethodProviderMakeTest {

    static final InputPort<NumberValue> IN = InputPort.of("in", NumberValue.class);
    static final OutputPort<NumberValue> OUT = OutputPort.of("out", NumberValue.class, Shape.number("m", "a distance"));

    /** Binds what it is given. */
    static final class Bound extends ProcessingMethod {
        Bound(Ports ports) {
            ports.inputs().forEach(p -> input(p, (v, s) -> { }));
            ports.outputs().forEach(this::output);
        }
    }

    static final class Provider extends SimpleMethodProvider<NoParams> {
        Provider(Ports listed, Ports bound) {
            super("bound", "binds what it is given", NoParams.class, listed, (l, p) -> new Bound(bound), Layer.PROCESSING);
        }
    }

    @Test
    void aMethodThatBindsTheListedPortsIsMadeWhateverTheOrder() {
        Provider provider = new Provider(Ports.of(IN, OUT), Ports.of(OUT, IN));

        assertThat(MethodProvider.make(provider, Layer.PROCESSING, new NoParams()).boundPorts().outputs())
                .containsExactly(OUT);
    }

    @Test
    void aPortBoundButNotListedOrListedButNotBoundIsRefusedByName() {
        InputPort<TextValue> extra = InputPort.of("extra", TextValue.class);
        Provider provider = new Provider(Ports.of(IN, OUT), Ports.of(extra, OUT));

        assertThatThrownBy(() -> MethodProvider.make(provider, Layer.PROCESSING, new NoParams()))
                .isInstanceOf(IllegalStateException.class)
                .hasMessage("method type 'bound' made a method whose ports are not the ones it lists: "
                        + "input in (number, latest) is listed but not bound; input extra (text, latest) is bound but not listed");
    }

    @Test
    void aPortBoundWithAnotherDeliveryOrShapeIsRefused() {
        Provider queue = new Provider(Ports.of(IN, OUT),
                Ports.of(InputPort.of("in", NumberValue.class, Delivery.queue(4)), OUT));
        Provider shape = new Provider(Ports.of(IN, OUT),
                Ports.of(IN, OutputPort.of("out", NumberValue.class, Shape.number("cm", "a distance"))));

        assertThatThrownBy(() -> MethodProvider.make(queue, Layer.PROCESSING, new NoParams()))
                .hasMessageContaining("input in (number, latest) is listed as NumberValue, Delivery[mode=LATEST");
        assertThatThrownBy(() -> MethodProvider.make(shape, Layer.PROCESSING, new NoParams()))
                .hasMessageContaining("output out (number) is listed as NumberValue, Shape[kind=NUMBER, unit=m");
    }

    @Test
    void aPortListedTwiceIsRefusedWhenTheListIsMade() {
        assertThatThrownBy(() -> Ports.of(IN, InputPort.of("in", TextValue.class)))
                .isInstanceOf(IllegalArgumentException.class).hasMessage("input 'in' is listed twice");
    }
}
