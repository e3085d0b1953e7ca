package org.example.habla;

import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.InputPort;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * A processing method that labels the nearest obstacle with hysteresis: {@code "near"} once its distance
 * drops below {@code nearM}, {@code "far"} once it rises above {@code farM}. It reads the {@code nearest}
 * record of a {@code nearest-distance} method (its {@code distanceM} field) and emits only when the label
 * changes.
 */
public final class Threshold extends ProcessingMethod {

    static final InputPort<RecordValue> NEAREST = InputPort.of("nearest", RecordValue.class, Delivery.latest());
    static final OutputPort<TextValue> LABEL = OutputPort.of("label", TextValue.class,
            Shape.text("near or far, emitted when it changes"));
    /** What the config wires, known without making a method. */
    static final Ports PORTS = Ports.of(NEAREST, LABEL);

    private final Output<TextValue> label = output(LABEL);
    private final Input<RecordValue> nearest = input(NEAREST, this::onNearest);

    private final ThresholdParams params;
    private String current = "";

    public Threshold(ThresholdParams params) {
        this.params = params;
    }

    private void onNearest(RecordValue obstacle, Sample s) {
        double distanceM = obstacle.number("distanceM");
        String next = distanceM < params.nearM() ? "near" : distanceM > params.farM() ? "far" : current;
        if (!next.equals(current)) {
            current = next;
            emit(label, new TextValue(next));
        }
    }
}
