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
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * The room speaker method, type {@code room-speaker}: something to say in the room (input {@code text}) as the
 * command of a networked speaker that speaks text itself, on output {@code command}:
 * {@code {"say": text, "volume": 0..100}}. Text is trimmed, cut to {@code maxLength}, and dropped when empty.
 */
public final class RoomSpeaker extends SensorActuatorMethod {

    private static final InputPort<TextValue> TEXT = InputPort.of("text", TextValue.class, Delivery.queue(16));
    private static final OutputPort<RecordValue> COMMAND = OutputPort.of("command", RecordValue.class,
            Shape.record("what to say and how loud (percent)", SpeakerCommand.LAYOUT));
    static final Ports PORTS = Ports.of(TEXT, COMMAND);

    private final Params params;
    private final Output<RecordValue> command = output(COMMAND);

    /** The params of a {@code room-speaker} method. */
    public record Params(
            @Param(value = "the speaker's volume", unit = "%", defaultValue = "50", min = 0, max = 100) int volume,
            @Param(value = "the longest text said; longer text is cut", unit = "char", defaultValue = "200",
                    min = 1, max = 10_000)
            int maxLength) {

    }

    RoomSpeaker(Params params) {
        this.params = params;
        input(TEXT, this::onText);
    }

    private void onText(TextValue value, Sample sample) {
        String text = value.text().strip();
        if (text.isEmpty()) {
            return;
        }
        if (text.length() > params.maxLength()) {
            text = text.substring(0, params.maxLength());
        }
        emit(command, RecordValue.of(new SpeakerCommand(text, params.volume())));
    }

    /** Makes {@code room-speaker} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("room-speaker", "Text to say in the room as a networked speaker's command", Params.class,
                    PORTS, (layer, p) -> new RoomSpeaker(p), Layer.SENSORS_ACTUATORS);
        }
    }
}
