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
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The blinds method, type {@code blinds}: how far blinds or a cover are open (input {@code open}: 0 closed,
 * 1 open) as a cover's command on output {@code command}: {@code {"position": 0..100}} (percent open, the
 * Zigbee2MQTT and Home Assistant convention; {@code invert} for covers that count closed). Sent when it changes.
 */
public final class Blinds extends SensorActuatorMethod {

    private static final InputPort<NumberValue> OPEN = InputPort.of("open", NumberValue.class, Delivery.queue(16));
    private static final OutputPort<RecordValue> COMMAND = OutputPort.of("command", RecordValue.class,
            Shape.record("the cover command: position in percent", CoverCommand.LAYOUT));
    static final Ports PORTS = Ports.of(OPEN, COMMAND);

    private final Params params;
    private final Output<RecordValue> command = output(COMMAND);
    private Integer last;

    /** The params of a {@code blinds} method. */
    public record Params(
            @Param(value = "the cover counts percent closed instead of open", defaultValue = "false") boolean invert) {

    }

    Blinds(Params params) {
        this.params = params;
        input(OPEN, this::onOpen);
    }

    private void onOpen(NumberValue value, Sample sample) {
        if (!Double.isFinite(value.value())) {
            return;
        }
        int percent = (int) Math.round(Math.max(0, Math.min(1, value.value())) * 100);
        int position = params.invert() ? 100 - percent : percent;
        if (last == null || last != position) {
            last = position;
            emit(command, RecordValue.of(new CoverCommand(position)));
        }
    }

    /** Makes {@code blinds} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("blinds", "How far blinds are open, 0..1, as a cover's position command in percent", Params.class,
                    PORTS, (layer, p) -> new Blinds(p), Layer.SENSORS_ACTUATORS);
        }
    }
}
