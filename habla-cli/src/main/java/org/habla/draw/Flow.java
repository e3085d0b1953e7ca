package org.habla.draw;

/** Which way data runs along a wire of the graph. */
public enum Flow {
    /** Upwards: interface → sensors → processing → virtual → control socket. */
    SENSING,
    /** Downwards: control socket → virtual → processing → actuators → interface. */
    ACTUATION,
    /** Between two methods of the same layer. */
    LATERAL
}
