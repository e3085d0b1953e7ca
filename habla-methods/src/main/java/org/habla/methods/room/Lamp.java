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
 * The lamp method, type {@code lamp}: a light's level (input {@code level}: 0 off, 1 full; values between dim a
 * dimmable lamp and switch a plain one on at {@code onAbove}) as the command most smart lamps take, on output
 * {@code command}: {@code {"state": "ON", "brightness": 0..maxBrightness}} or {@code {"state": "OFF"}} (the
 * Zigbee2MQTT and Home Assistant JSON light schema).
 *
 * <p>A command is sent when it changes what the lamp does, as far as the method knows it: the lamp's own state
 * (optional input {@code state}, the lamp's state message, e.g. {@code {"state":"ON","brightness":203}}), so a
 * lamp switched at the wall is seen, and a level that differs from it is sent again. The same command is not
 * repeated while the lamp has not answered it for {@code resendMs}, so a controller that repeats itself does not
 * flood the broker; after that it goes again (a lamp without a state input never answers, so a repeated level is
 * sent at most every {@code resendMs}). A command sent while the method is stale (the lamp, its broker or the
 * link to it is down, so the command is dropped on the way) does not count as sent. Output {@code level} echoes
 * the level sent; output {@code reported} the level the lamp says it is at.
 */
public final class Lamp extends SensorActuatorMethod {

    private static final InputPort<NumberValue> LEVEL = InputPort.of("level", NumberValue.class, Delivery.queue(16));
    private static final InputPort<RecordValue> STATE = InputPort.optional("state", RecordValue.class,
            Delivery.latest());
    private static final OutputPort<RecordValue> COMMAND = OutputPort.of("command", RecordValue.class,
            Shape.record("the lamp command: state ON/OFF and brightness", LampCommand.LAYOUT));
    private static final OutputPort<NumberValue> ECHO = OutputPort.of("level", NumberValue.class,
            Shape.number("", "the level the lamp was told, 0..1"));
    private static final OutputPort<NumberValue> REPORTED = OutputPort.of("reported", NumberValue.class,
            Shape.number("", "the level the lamp says it is at, 0..1 (from input state)"));
    static final Ports PORTS = Ports.of(LEVEL, STATE, COMMAND, ECHO, REPORTED);

    private final Params params;
    private final Output<RecordValue> command = output(COMMAND);
    private final Output<NumberValue> echo = output(ECHO);
    private final Output<NumberValue> reportedLevel = output(REPORTED);
    /** What the lamp last said it does; null until it says. */
    private RecordValue reported;
    /** The last command sent while fresh that the lamp has not answered since; null when none. */
    private LampCommand pending;
    private long pendingMicros;

    /**
     * The params of a {@code lamp} method.
     *
     * @param dimmable      whether the lamp takes a brightness
     * @param maxBrightness the device's brightness at full level
     * @param onAbove       a plain lamp is on at levels above this
     * @param resendMs      how long an unanswered command is not repeated
     */
    public record Params(
            @Param(value = "whether the lamp takes a brightness", defaultValue = "true") boolean dimmable,
            @Param(value = "the device's brightness at full level (Zigbee: 254)", defaultValue = "254",
                    min = 1, max = 65_535)
            int maxBrightness,
            @Param(value = "a lamp that is not dimmable is on at levels above this", defaultValue = "0.5",
                    min = 0, max = 1)
            double onAbove,
            @Param(value = "how long the same command is not sent again while the lamp has not answered it", unit = "ms",
                    defaultValue = "2000",
                    min = 1, max = 3_600_000)
            int resendMs) {

    }

    Lamp(Params params) {
        this.params = params;
        input(LEVEL, this::onLevel);
        input(STATE, this::onState);
    }

    private void onLevel(NumberValue value, Sample sample) {
        double v = value.value();
        if (!Double.isFinite(v)) {
            return;
        }
        v = Math.max(0, Math.min(1, v));
        LampCommand next;
        double sent;
        if (params.dimmable()) {
            int brightness = (int) Math.round(v * params.maxBrightness());
            next = brightness == 0 ? LampCommand.OFF : LampCommand.dimmedTo(brightness);
            sent = brightness / (double) params.maxBrightness();
        } else {
            boolean on = v > params.onAbove();
            next = on ? LampCommand.ON : LampCommand.OFF;
            sent = on ? 1 : 0;
        }
        boolean fresh = !stale();
        if (fresh && reported != null && pending == null && does(reported, next)) {
            return;
        }
        long now = nowMicros();
        if (fresh && next.equals(pending) && now - pendingMicros < params.resendMs() * 1_000L) {
            return;
        }
        pending = fresh ? next : null;
        pendingMicros = now;
        emit(command, RecordValue.of(next));
        emit(echo, new NumberValue(sent));
    }

    /** The lamp says what it does: a command it answers is no longer pending, and a wall switch is seen. */
    private void onState(RecordValue state, Sample sample) {
        reported = state;
        pending = null;
        emit(reportedLevel, new NumberValue(level(state)));
    }

    /** Whether a lamp in state {@code state} (its own message) already does what {@code command} asks. */
    private boolean does(RecordValue state, LampCommand command) {
        boolean on = isOn(state);
        if (!command.on()) {
            return !on;
        }
        if (!on) {
            return false;
        }
        return !params.dimmable() || Math.abs(brightness(state) - command.brightness()) <= 1;
    }

    private double level(RecordValue state) {
        if (!isOn(state)) {
            return 0;
        }
        return params.dimmable() && Double.isFinite(brightness(state))
                ? Math.max(0, Math.min(1, brightness(state) / params.maxBrightness())) : 1;
    }

    private static boolean isOn(RecordValue r) {
        return r.get("state").asText("").equalsIgnoreCase("ON");
    }

    private static double brightness(RecordValue r) {
        return r.get("brightness").isNumber() ? r.get("brightness").doubleValue() : Double.NaN;
    }

    /** Makes {@code lamp} methods. */
    public static final class Provider extends SimpleMethodProvider<Params> {
        public Provider() {
            super("lamp", "A light's level 0..1 as a smart lamp's command: state ON/OFF and brightness", Params.class,
                    PORTS, (layer, p) -> new Lamp(p), Layer.SENSORS_ACTUATORS);
        }
    }
}
