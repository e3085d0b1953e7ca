package org.habla.methods.room;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.plugin.Param;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;

/**
 * The light sensor method, type {@code light-sensor}: illuminance in lux (input {@code lux}), checked and
 * smoothed, on output {@code lux}. A reading that is negative or not finite is dropped and counted; one above
 * {@code maxLux} is clipped. With {@code smoothing} s between 0 and 1, each output is
 * {@code s × previous + (1 − s) × reading}, so a flickering sensor does not make lamps flicker.
 */
public final class LightSensor extends SensorActuatorMethod {

    private static final InputPort<NumberValue> LUX_IN = InputPort.of("lux", NumberValue.class, Delivery.latest());
    private static final OutputPort<NumberValue> LUX = OutputPort.of("lux", NumberValue.class,
            Shape.number("lx", "illuminance"));
    static final Ports PORTS = Ports.of(LUX_IN, LUX);

    private final Params params;
    private final Output<NumberValue> lux = output(LUX);
    private Double smoothed;
    private long dropped;

    /**
     * The params of a {@code light-sensor} method.
     *
     * @param maxLux    readings above this are clipped to it
     * @param smoothing the weight of the previous output, 0 (none) to below 1
     */
    public record Params(
            @Param(value = "readings above this are clipped to it", unit = "lx", defaultValue = "100000",
                    greaterThan = 0)
            double maxLux,
            @Param(value = "the weight of the previous output in each new one: 0 (none) to 0.99",
                    defaultValue = "0", min = 0, max = 0.99) double smoothing) {

    }

    LightSensor(Params params) {
        this.params = params;
        input(LUX_IN, this::onLux);
    }

    private void onLux(NumberValue value, Sample sample) {
        double v = value.value();
        if (!Double.isFinite(v) || v < 0) {
            if (dropped++ == 0) {
                log().warn("{}: a reading of {} lx is no illuminance; dropped (further ones only counted)", id(), v);
            }
            return;
        }
        v = Math.min(v, params.maxLux());
        smoothed = smoothed == null ? v : params.smoothing() * smoothed + (1 - params.smoothing()) * v;
        emit(lux, new NumberValue(smoothed));
    }

    /** Readings dropped since start. */
    public long dropped() {
        return dropped;
    }

    /** Makes {@code light-sensor} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("light-sensor", "Illuminance in lux, checked, clipped and optionally smoothed", Params.class,
                    PORTS, (layer, p) -> new LightSensor(p), Layer.SENSORS_ACTUATORS);
        }
    }
}
