package org.habla.config;

import java.util.List;
import java.util.Set;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.VirtualMethod;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.NoParams;
import org.habla.plugin.Param;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;

/**
 * Small real methods of each layer, enough to wire a Pioneer-like graph in config tests:
 * {@code sonar → nearest → distance-angle} going up, {@code action → safety → wheels} going down.
 */
final class TestMethods {

    private TestMethods() {
    }

    /** The params of {@code sonar}: declared ranges, one on each element of a list, and a rule across two. */
    record SonarParams(
            @Param(value = "Ranges beyond this are reported as this", unit = "m", defaultValue = "5.0", greaterThan = 0)
            double maxRangeM,
            @Param(value = "Ranges below this are ignored", unit = "m", defaultValue = "0.1", min = 0) double minRangeM,
            @Param(value = "Which transducers to use; empty means all", defaultValue = "[]", min = 0, max = 31)
            List<Integer> use) {
        SonarParams {
            use = List.copyOf(use);
            if (minRangeM >= maxRangeM) {
                throw new IllegalArgumentException("the minimum range must be below the maximum");
            }
        }
    }

    /** The params of {@code wheels}: a primitive (required) component and an enum. */
    record WheelsParams(
            @Param(value = "Distance between the wheels", unit = "m") double trackM,
            @Param(value = "How a stop is made", defaultValue = "\"SOFT\"") Stop stop) {
        enum Stop { SOFT, HARD }
    }

    /** The params of {@code step}: a text its constructor checks, and a flag. */
    record StepParams(
            @Param(value = "Label of the step", defaultValue = "\"step\"") String label,
            @Param(value = "Whether to log each step", defaultValue = "false") boolean verbose) {
        StepParams {
            if (label.isBlank()) {
                throw new IllegalArgumentException("label must not be blank");
            }
        }
    }

    static final class Sonar extends SensorActuatorMethod {
        static final InputPort<VectorValue> IN = InputPort.of("ranges", VectorValue.class);
        static final OutputPort<VectorValue> OUT = OutputPort.of("ranges", VectorValue.class);
        static final Ports PORTS = Ports.of(IN, OUT);
        final Output<VectorValue> out = output(OUT);
        final Input<VectorValue> in = input(IN, (v, s) -> emit(out, v));
    }

    static final class Wheels extends SensorActuatorMethod {
        static final InputPort<VectorValue> VELOCITY = InputPort.of("velocity", VectorValue.class, Delivery.queue(4));
        static final OutputPort<VectorValue> MOTION = OutputPort.of("motion", VectorValue.class);
        static final Ports PORTS = Ports.of(VELOCITY, MOTION);
        final Output<VectorValue> motion = output(MOTION);
        final Input<VectorValue> velocity = input(VELOCITY, (v, s) -> emit(motion, v));
    }

    static final class Nearest extends ProcessingMethod {
        static final InputPort<VectorValue> RANGES = InputPort.of("ranges", VectorValue.class);
        static final OutputPort<NumberValue> NEAREST = OutputPort.of("nearest", NumberValue.class);
        static final Ports PORTS = Ports.of(RANGES, NEAREST);
        final Output<NumberValue> nearest = output(NEAREST);
        final Input<VectorValue> ranges = input(RANGES, (v, s) -> emit(nearest, new NumberValue(0)));
    }

    static final class Safety extends ProcessingMethod {
        static final InputPort<VectorValue> VELOCITY_IN = InputPort.of("velocity", VectorValue.class);
        static final InputPort<NumberValue> NEAREST = InputPort.optional("nearest", NumberValue.class,
                Delivery.latest());
        static final OutputPort<VectorValue> VELOCITY_OUT = OutputPort.of("velocity", VectorValue.class);
        static final Ports PORTS = Ports.of(VELOCITY_IN, NEAREST, VELOCITY_OUT);
        final Output<VectorValue> out = output(VELOCITY_OUT);
        final Input<VectorValue> velocity = input(VELOCITY_IN, (v, s) -> emit(out, v));
        final Input<NumberValue> nearest = input(NEAREST, (v, s) -> { });
    }

    static final class DistanceAngle extends VirtualMethod {
        static final InputPort<NumberValue> NEAREST = InputPort.of("nearest", NumberValue.class);
        static final OutputPort<RecordValue> OUT = OutputPort.of("distance_angle", RecordValue.class);
        static final Ports PORTS = Ports.of(NEAREST, OUT);
        final Output<RecordValue> out = output(OUT);
        final Input<NumberValue> nearest = input(NEAREST, (v, s) -> { });
    }

    static final class Action extends VirtualMethod {
        static final InputPort<TextValue> ACTION = InputPort.of("action", TextValue.class, Delivery.queue(8));
        static final OutputPort<VectorValue> VELOCITY = OutputPort.of("velocity", VectorValue.class);
        static final Ports PORTS = Ports.of(ACTION, VELOCITY);
        final Output<VectorValue> velocity = output(VELOCITY);
        final Input<TextValue> action = input(ACTION, (v, s) -> { });
    }

    /** Takes text and gives nothing: cannot be exposed unless it takes control values. */
    static final class Sink extends VirtualMethod {
        static final InputPort<TextValue> TEXT = InputPort.of("text", TextValue.class);
        static final Ports PORTS = Ports.of(TEXT);
        final Input<TextValue> text = input(TEXT, (v, s) -> { });
    }

    /** Passes any payload on; placeable in the processing and virtual layers. */
    static Method relay(Layer layer) {
        return layer == Layer.PROCESSING ? new ProcessingRelay() : new VirtualRelay();
    }

    static final InputPort<Payload> RELAY_IN = InputPort.of("in", Payload.class);
    static final OutputPort<Payload> RELAY_OUT = OutputPort.of("out", Payload.class);
    static final Ports RELAY = Ports.of(RELAY_IN, RELAY_OUT);

    static final class ProcessingRelay extends ProcessingMethod {
        final Output<Payload> out = output(RELAY_OUT);
        final Input<Payload> in = input(RELAY_IN, (v, s) -> emit(out, v));
    }

    static final class VirtualRelay extends VirtualMethod {
        final Output<Payload> out = output(RELAY_OUT);
        final Input<Payload> in = input(RELAY_IN, (v, s) -> emit(out, v));
    }

    /** Every test method type. */
    static List<MethodProvider<?>> providers() {
        Set<Layer> sa = Set.of(Layer.SENSORS_ACTUATORS);
        Set<Layer> proc = Set.of(Layer.PROCESSING);
        Set<Layer> virt = Set.of(Layer.VIRTUAL);
        return List.of(
                new TestProvider<>("sonar", sa, SonarParams.class, Sonar.PORTS, (l, p) -> new Sonar()),
                new TestProvider<>("wheels", sa, WheelsParams.class, Wheels.PORTS, (l, p) -> new Wheels()),
                new TestProvider<>("nearest-distance", proc, NoParams.class, Nearest.PORTS, (l, p) -> new Nearest()),
                new TestProvider<>("safety", proc, StepParams.class, Safety.PORTS, (l, p) -> new Safety()),
                new TestProvider<>("distance-angle", virt, NoParams.class, DistanceAngle.PORTS,
                        (l, p) -> new DistanceAngle()),
                new TestProvider<>("action", virt, NoParams.class, Action.PORTS, (l, p) -> new Action()),
                new TestProvider<>("sink", virt, NoParams.class, Sink.PORTS, (l, p) -> new Sink()),
                new TestProvider<>("relay", Set.of(Layer.PROCESSING, Layer.VIRTUAL), NoParams.class, RELAY,
                        (l, p) -> relay(l)),
                new TestProvider<>("broken-model", proc, NoParams.class, (l, p) -> {
                    throw new IllegalStateException("the model file is missing");
                }, (l, p) -> {
                    throw new AssertionError("a type whose ports cannot be listed is never made");
                }),
                new TestProvider<>("unmakeable", proc, NoParams.class, RELAY, (l, p) -> {
                    throw new IllegalStateException("the model file is missing");
                }));
    }
}
