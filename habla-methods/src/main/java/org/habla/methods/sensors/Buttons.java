package org.habla.methods.sensors;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * The general buttons method, type {@code buttons}: it reads a record of button and touch-sensor
 * values (input {@code buttons}, one number per button, e.g. {@code {"headTouch": 0.8, "backMiddle": 0}})
 * and says which are pressed. Output {@code pressed} is a record of booleans by button name, for
 * every reading; output {@code touch} is the button's name, once, each time a button goes down. A
 * button is pressed when its value reaches {@code threshold} and released when it falls below
 * {@code releaseThreshold}, so a value hovering at the threshold does not chatter. Fields that are
 * not finite numbers are ignored.
 */
public final class Buttons extends SensorActuatorMethod {

    private static final OutputPort<RecordValue> PRESSED = OutputPort.of("pressed", RecordValue.class,
            Shape.record("true for each button held down, by name", ButtonStates.LAYOUT));
    private static final OutputPort<TextValue> TOUCH = OutputPort.of("touch", TextValue.class,
            Shape.text("the name of a button, once when it goes down"));
    private static final InputPort<RecordValue> BUTTONS = InputPort.of("buttons", RecordValue.class,
            Delivery.queue(32));
    static final Ports PORTS = Ports.of(PRESSED, TOUCH, BUTTONS);

    private final ButtonsParams params;
    private final Output<RecordValue> pressed = output(PRESSED);
    private final Output<TextValue> touch = output(TOUCH);
    private final Map<String, Boolean> down = new LinkedHashMap<>();

    Buttons(ButtonsParams params) {
        this.params = params;
        input(BUTTONS, this::onButtons);
    }

    private void onButtons(RecordValue record, Sample sample) {
        JsonNode fields = record.json();
        List<String> names = params.names().isEmpty() ? fieldNames(fields) : params.names();
        List<String> edges = new ArrayList<>();
        Map<String, Boolean> out = new LinkedHashMap<>();
        for (String name : names) {
            JsonNode v = fields.get(name);
            boolean was = down.getOrDefault(name, false);
            boolean now = was;
            if (v != null && v.isNumber() && Double.isFinite(v.doubleValue())) {
                double x = v.doubleValue();
                now = was ? x >= params.releaseThreshold() : x >= params.threshold();
            }
            down.put(name, now);
            out.put(name, now);
            if (now && !was) {
                edges.add(name);
            }
        }
        emit(pressed, RecordValue.of(new ButtonStates(out)));
        edges.forEach(name -> emit(touch, new TextValue(name)));
    }

    private static List<String> fieldNames(JsonNode fields) {
        List<String> names = new ArrayList<>();
        fields.fieldNames().forEachRemaining(names::add);
        return names;
    }

    /** Makes {@code buttons} methods. */
    public static final class Provider extends SimpleMethodProvider<ButtonsParams> {
        public Provider() {
            super("buttons", "Says which buttons and touch sensors are pressed, and names each new press",
                    ButtonsParams.class, PORTS, (layer, p) -> new Buttons(p), Layer.SENSORS_ACTUATORS);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
