package org.habla.sample;

/** A single number (a distance, an energy, a reward). */
public record NumberValue(double value) implements Payload {

    @Override
    public PayloadKind kind() {
        return PayloadKind.NUMBER;
    }
}
