package org.habla.sample;

import java.util.Arrays;

/** A fixed sequence of numbers (sonar ranges, a spectrum, wheel velocities). */
public final class VectorValue implements Payload {

    private final double[] values;

    private VectorValue(double[] values) {
        this.values = values;
    }

    /** A vector holding a copy of {@code values}. */
    public static VectorValue of(double... values) {
        return new VectorValue(values.clone());
    }

    /** A vector that takes ownership of {@code values}; the caller must not touch the array again. */
    public static VectorValue wrap(double[] values) {
        return new VectorValue(values);
    }

    public int size() {
        return values.length;
    }

    public double get(int index) {
        return values[index];
    }

    /** A copy of the values. */
    public double[] toArray() {
        return values.clone();
    }

    @Override
    public PayloadKind kind() {
        return PayloadKind.VECTOR;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof VectorValue v && Arrays.equals(values, v.values);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(values);
    }

    @Override
    public String toString() {
        return "VectorValue" + Arrays.toString(values);
    }
}
