package org.example.habla;

import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.Output;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;

/**
 * A processing method that turns a number into a label with hysteresis: {@code "near"} once the
 * value drops below {@code nearM}, {@code "far"} once it rises above {@code farM}. It emits only
 * when the label changes.
 */
public final class Threshold extends ProcessingMethod {

    private final Output<TextValue> label = output("label", TextValue.class,
            Shape.text("near or far, emitted when it changes"));
    private final Input<NumberValue> value = input("value", NumberValue.class, Delivery.latest(), this::onValue);

    private final ThresholdParams params;
    private String current = "";

    public Threshold(ThresholdParams params) {
        this.params = params;
    }

    private void onValue(NumberValue v, Sample s) {
        String next = current;
        if (v.value() < params.nearM()) {
            next = "near";
        } else if (v.value() > params.farM()) {
            next = "far";
        }
        if (!next.equals(current)) {
            current = next;
            emit(label, new TextValue(next));
        }
    }
}
