package org.habla.draw;

import org.habla.method.Layer;

/** The horizontal bands of the picture, top to bottom: the control sockets, the three layers, the interfaces. */
public enum Row {
    CONTROL("control architecture"),
    VIRTUAL("virtual information layer"),
    PROCESSING("processing layer"),
    SENSORS_ACTUATORS("sensors & actuators layer"),
    INTERFACES("interfaces");

    private final String title;

    Row(String title) {
        this.title = title;
    }

    /** The band's title as drawn. */
    public String title() {
        return title;
    }

    /** The band of a layer's methods. */
    public static Row of(Layer layer) {
        return switch (layer) {
            case VIRTUAL -> VIRTUAL;
            case PROCESSING -> PROCESSING;
            case SENSORS_ACTUATORS -> SENSORS_ACTUATORS;
        };
    }
}
