package org.habla.methods.room;

import java.time.Duration;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.plugin.Param;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;

/**
 * The presence method, type {@code presence}: whether someone is in a zone, from a motion sensor (input
 * {@code motion}: 1 while it sees movement) and a door contact (input {@code door}: any change of its value).
 * Motion sensors fall quiet when a person sits still, so presence is held for {@code holdMs} after the last
 * motion; a door that opens or closes means someone passed, held for {@code doorHoldMs}. Output {@code present}
 * (1 or 0) is sent when it changes. Either input may be left unwired.
 */
public final class Presence extends ProcessingMethod {

    private static final Duration TICK = Duration.ofMillis(100);

    private static final InputPort<NumberValue> MOTION = InputPort.optional("motion", NumberValue.class,
            Delivery.queue(32));
    private static final InputPort<NumberValue> DOOR = InputPort.optional("door", NumberValue.class,
            Delivery.queue(32));
    private static final OutputPort<NumberValue> PRESENT = OutputPort.of("present", NumberValue.class,
            Shape.number("", "1 while someone is in the zone (held after the last motion), else 0"));
    static final Ports PORTS = Ports.of(MOTION, DOOR, PRESENT);

    private final Params params;
    private final Output<NumberValue> present = output(PRESENT);
    private long motionUntilMicros = Long.MIN_VALUE;
    private long doorUntilMicros = Long.MIN_VALUE;
    private boolean moving;
    private Double door;
    private Boolean sent;

    /**
     * The params of a {@code presence} method.
     *
     * @param holdMs     how long presence lasts after the last motion
     * @param doorHoldMs how long presence lasts after the door opened or closed
     */
    public record Params(
            @Param(value = "presence lasts this long after the last motion", unit = "ms", defaultValue = "30000",
                    min = 0, max = 86_400_000)
            int holdMs,
            @Param(value = "presence lasts this long after the door opened or closed", unit = "ms",
                    defaultValue = "10000", min = 0, max = 86_400_000) int doorHoldMs) {

    }

    Presence(Params params) {
        this.params = params;
        input(MOTION, this::onMotion);
        input(DOOR, this::onDoor);
        tickEvery(TICK);
    }

    private void onMotion(NumberValue value, Sample sample) {
        moving = value.value() >= 0.5;
        if (moving) {
            motionUntilMicros = nowMicros() + params.holdMs() * 1000L;
        }
        update();
    }

    private void onDoor(NumberValue value, Sample sample) {
        if (door != null && door != value.value()) {
            doorUntilMicros = nowMicros() + params.doorHoldMs() * 1000L;
        }
        door = value.value();
        update();
    }

    @Override
    protected void onTick(long nowMicros) {
        if (Boolean.TRUE.equals(sent)) {
            update();
        }
    }

    private void update() {
        long now = nowMicros();
        boolean isPresent = moving || now < motionUntilMicros || now < doorUntilMicros;
        if (sent == null || sent != isPresent) {
            sent = isPresent;
            emit(present, new NumberValue(isPresent ? 1 : 0), now);
        }
    }

    /** Makes {@code presence} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("presence", "Whether someone is in a zone, from motion (held for holdMs) and door contacts",
                    Params.class, PORTS, (layer, p) -> new Presence(p), Layer.PROCESSING);
        }
    }
}
