package org.habla.methods.sensors;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * The keyboard method, type {@code keyboard}: the lines someone types (input {@code line}, e.g. a
 * {@code text-lines} interface's {@code line} channel) as clean text on output {@code line}. Control
 * characters become spaces, runs of spaces one space, the ends are trimmed and a line longer than
 * {@code maxLength} is cut; a line left empty is dropped and counted.
 */
public final class Keyboard extends SensorActuatorMethod {

    private static final OutputPort<TextValue> LINE_OUT = OutputPort.of("line", TextValue.class,
            Shape.text("a typed line, trimmed, without control characters"));
    private static final InputPort<TextValue> LINE_IN = InputPort.of("line", TextValue.class, Delivery.queue(64));
    static final Ports PORTS = Ports.of(LINE_OUT, LINE_IN);

    private final KeyboardParams params;
    private final Output<TextValue> out = output(LINE_OUT);

    private long dropped;
    private long cut;

    Keyboard(KeyboardParams params) {
        this.params = params;
        input(LINE_IN, this::onLine);
    }

    private void onLine(TextValue value, Sample sample) {
        String text = clean(value.text());
        if (text.isEmpty()) {
            dropped++;
            return;
        }
        if (text.length() > params.maxLength()) {
            cut++;
            int end = params.maxLength();
            if (Character.isHighSurrogate(text.charAt(end - 1))) {
                end--;
            }
            text = text.substring(0, end).strip();
        }
        emit(out, new TextValue(text));
    }

    static String clean(String raw) {
        StringBuilder b = new StringBuilder(Math.min(raw.length(), 4096));
        boolean space = false;
        for (int i = 0; i < raw.length(); i++) {
            char c = raw.charAt(i);
            boolean blank = Character.isWhitespace(c) || Character.isISOControl(c) || Character.getType(c) == Character.FORMAT;
            if (blank) {
                space = b.length() > 0;
                continue;
            }
            if (space) {
                b.append(' ');
                space = false;
            }
            b.append(c);
        }
        return b.toString();
    }

    /** Lines dropped because nothing was left of them, since start. */
    public long dropped() {
        return dropped;
    }

    /** Lines cut to the maximum length, since start. */
    public long cut() {
        return cut;
    }

    /** Makes {@code keyboard} methods. */
    public static final class Provider extends SimpleMethodProvider<KeyboardParams> {
        public Provider() {
            super("keyboard", "Typed lines, trimmed and without control characters, cut to a maximum length",
                    KeyboardParams.class, PORTS, (layer, p) -> new Keyboard(p), Layer.SENSORS_ACTUATORS);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
