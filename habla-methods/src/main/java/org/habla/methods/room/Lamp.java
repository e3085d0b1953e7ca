package org.habla.methods.room;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.methods.ParamRules;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.NumberValue;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The lamp method, type {@code lamp}: a light's level (input {@code level}: 0 off, 1 full; values between dim a
 * dimmable lamp and switch a plain one on at {@code onAbove}) as the command most smart lamps take, on output
 * {@code command}: {@code {"state": "ON", "brightness": 0..maxBrightness}} or {@code {"state": "OFF"}} (the
 * Zigbee2MQTT and Home Assistant JSON light schema). A command is sent only when it changes what the lamp does, so
 * a controller that repeats itself does not flood the broker. Output {@code level} echoes the level sent.
 */
public final class Lamp extends SensorActuatorMethod {

    private static final InputPort<NumberValue> LEVEL = InputPort.of("level", NumberValue.class, Delivery.queue(16));
    private static final OutputPort<RecordValue> COMMAND = OutputPort.of("command", RecordValue.class,
            Shape.record("the lamp command: state ON/OFF and brightness", "state", "brightness"));
    private static final OutputPort<NumberValue> ECHO = OutputPort.of("level", NumberValue.class,
            Shape.number("", "the level the lamp was told, 0..1"));
    static final Ports PORTS = Ports.of(LEVEL, COMMAND, ECHO);

    private final Params params;
    private final Output<RecordValue> command = output(COMMAND);
    private final Output<NumberValue> echo = output(ECHO);
    private RecordValue last;

    /**
     * The params of a {@code lamp} method.
     *
     * @param dimmable      whether the lamp takes a brightness
     * @param maxBrightness the device's brightness at full level
     * @param onAbove       a plain lamp is on at levels above this
     */
    public record Params(
            @Param(value = "whether the lamp takes a brightness", defaultValue = "true") Boolean dimmable,
            @Param(value = "the device's brightness at full level (Zigbee: 254)", defaultValue = "254")
            Integer maxBrightness,
            @Param(value = "a lamp that is not dimmable is on at levels above this", defaultValue = "0.5")
            Double onAbove) {

        public Params {
            dimmable = ParamDefaults.or(Params.class, "dimmable", dimmable);
            maxBrightness = ParamRules.within(Params.class, "maxBrightness", maxBrightness, 1, 65_535);
            onAbove = ParamRules.within(Params.class, "onAbove", onAbove, 0, 1);
        }
    }

    Lamp(Params params) {
        this.params = params;
        input(LEVEL, this::onLevel);
    }

    private void onLevel(NumberValue value, Sample sample) {
        double v = value.value();
        if (!Double.isFinite(v)) {
            return;
        }
        v = Math.max(0, Math.min(1, v));
        RecordValue next;
        double sent;
        if (params.dimmable()) {
            int brightness = (int) Math.round(v * params.maxBrightness());
            next = brightness == 0 ? off() : RecordValue.builder().put("state", "ON").put("brightness", brightness).build();
            sent = brightness / (double) params.maxBrightness();
        } else {
            boolean on = v > params.onAbove();
            next = on ? RecordValue.builder().put("state", "ON").build() : off();
            sent = on ? 1 : 0;
        }
        if (!next.equals(last)) {
            last = next;
            emit(command, next);
            emit(echo, new NumberValue(sent));
        }
    }

    private static RecordValue off() {
        return RecordValue.builder().put("state", "OFF").build();
    }

    /** Makes {@code lamp} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("lamp", "A light's level 0..1 as a smart lamp's command: state ON/OFF and brightness", Params.class,
                    PORTS, (layer, p) -> new Lamp(p), Layer.SENSORS_ACTUATORS);
        }
    }
}
