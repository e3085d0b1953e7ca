package org.example.habla;

import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.Output;
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

    private final Output<TextValue> label = output("label", TextValue.class,
            Shape.text("near or far, emitted when it changes"));
    private final Input<RecordValue> nearest = input("nearest", RecordValue.class, Delivery.latest(),
            this::onNearest);

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
