package org.habla.method;

import java.util.Locale;

/**
 * The three layers of the HABLA, in order of increasing processing. A method exchanges data
 * only with methods of its own layer or a neighbouring one.
 */
public enum Layer {
    SENSORS_ACTUATORS,
    PROCESSING,
    VIRTUAL;

    /** The name used in configs: {@code sensors_actuators}, {@code processing}, {@code virtual}. */
    public String configName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** Whether data may flow directly between a method of this layer and one of {@code other}. */
    public boolean neighbours(Layer other) {
        return Math.abs(ordinal() - other.ordinal()) <= 1;
    }

    public static Layer fromConfig(String name) {
        for (Layer l : values()) {
            if (l.configName().equals(name)) {
                return l;
            }
        }
        throw new IllegalArgumentException("unknown layer '" + name
                + "' (expected sensors_actuators, processing or virtual)");
    }
}
