package org.habla.config;

import java.util.List;
import java.util.Set;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Output;
import org.habla.method.ProcessingMethod;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.VirtualMethod;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.NoParams;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;
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

    /** The params of {@code sonar}. */
    record SonarParams(
            @Param(value = "Ranges beyond this are reported as this", unit = "m", defaultValue = "5.0") Double maxRangeM,
            @Param(value = "Ranges below this are ignored", unit = "m", defaultValue = "0.1") Double minRangeM,
            @Param(value = "Which transducers to use; empty means all", defaultValue = "[]") List<Integer> use) {
        SonarParams {
            maxRangeM = ParamDefaults.or(SonarParams.class, "maxRangeM", maxRangeM);
            minRangeM = ParamDefaults.or(SonarParams.class, "minRangeM", minRangeM);
            use = List.copyOf(ParamDefaults.or(SonarParams.class, "use", use));
            if (!(maxRangeM > 0)) {
                throw new IllegalArgumentException("maxRangeM must be positive, was " + maxRangeM);
            }
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

        WheelsParams {
            stop = ParamDefaults.or(WheelsParams.class, "stop", stop);
        }
    }

    /** The params of {@code step}: a text and a flag. */
    record StepParams(
            @Param(value = "Label of the step", defaultValue = "\"step\"") String label,
            @Param(value = "Whether to log each step", defaultValue = "false") Boolean verbose) {
        StepParams {
            label = ParamDefaults.or(StepParams.class, "label", label);
            verbose = ParamDefaults.or(StepParams.class, "verbose", verbose);
        }
    }

    static final class Sonar extends SensorActuatorMethod {
        final Output<VectorValue> out = output("ranges", VectorValue.class);
        final Input<VectorValue> in = input("ranges", VectorValue.class, (v, s) -> emit(out, v));
    }

    static final class Wheels extends SensorActuatorMethod {
        final Output<VectorValue> motion = output("motion", VectorValue.class);
        final Input<VectorValue> velocity = input("velocity", VectorValue.class, Delivery.queue(4), (v, s) -> emit(motion, v));
    }

    static final class Nearest extends ProcessingMethod {
        final Output<NumberValue> nearest = output("nearest", NumberValue.class);
        final Input<VectorValue> ranges = input("ranges", VectorValue.class, (v, s) -> emit(nearest, new NumberValue(0)));
    }

    static final class Safety extends ProcessingMethod {
        final Output<VectorValue> out = output("velocity", VectorValue.class);
        final Input<VectorValue> velocity = input("velocity", VectorValue.class, (v, s) -> emit(out, v));
        final Input<NumberValue> nearest = optionalInput("nearest", NumberValue.class, Delivery.latest(), (v, s) -> { });
    }

    static final class DistanceAngle extends VirtualMethod {
        final Output<RecordValue> out = output("distance_angle", RecordValue.class);
        final Input<NumberValue> nearest = input("nearest", NumberValue.class, (v, s) -> { });
    }

    static final class Action extends VirtualMethod {
        final Output<VectorValue> velocity = output("velocity", VectorValue.class);
        final Input<TextValue> action = input("action", TextValue.class, Delivery.queue(8), (v, s) -> { });
    }

    /** Takes text and gives nothing: cannot be exposed unless it takes control values. */
    static final class Sink extends VirtualMethod {
        final Input<TextValue> text = input("text", TextValue.class, (v, s) -> { });
    }

    /** Passes any payload on; placeable in the processing and virtual layers. */
    static Method relay(Layer layer) {
        return layer == Layer.PROCESSING ? new ProcessingRelay() : new VirtualRelay();
    }

    static final class ProcessingRelay extends ProcessingMethod {
        final Output<Payload> out = output("out", Payload.class);
        final Input<Payload> in = input("in", Payload.class, (v, s) -> emit(out, v));
    }

    static final class VirtualRelay extends VirtualMethod {
        final Output<Payload> out = output("out", Payload.class);
        final Input<Payload> in = input("in", Payload.class, (v, s) -> emit(out, v));
    }

    /** Every test method type. */
    static List<MethodProvider<?>> providers() {
        Set<Layer> sa = Set.of(Layer.SENSORS_ACTUATORS);
        Set<Layer> proc = Set.of(Layer.PROCESSING);
        Set<Layer> virt = Set.of(Layer.VIRTUAL);
        return List.of(
                new TestProvider<>("sonar", sa, SonarParams.class, (l, p) -> new Sonar()),
                new TestProvider<>("wheels", sa, WheelsParams.class, (l, p) -> new Wheels()),
                new TestProvider<>("nearest-distance", proc, NoParams.class, (l, p) -> new Nearest()),
                new TestProvider<>("safety", proc, StepParams.class, (l, p) -> new Safety()),
                new TestProvider<>("distance-angle", virt, NoParams.class, (l, p) -> new DistanceAngle()),
                new TestProvider<>("action", virt, NoParams.class, (l, p) -> new Action()),
                new TestProvider<>("sink", virt, NoParams.class, (l, p) -> new Sink()),
                new TestProvider<>("relay", Set.of(Layer.PROCESSING, Layer.VIRTUAL), NoParams.class,
                        (l, p) -> relay(l)),
                new TestProvider<>("broken-model", proc, NoParams.class, (l, p) -> {
                    throw new IllegalStateException("the model file is missing");
                }));
    }
}
