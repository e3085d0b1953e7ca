package org.habla.method;

/**
 * Base of every method of the sensors &amp; actuators layer: methods that store readings from an interface channel and send commands to one.
 * See {@link Method} for the threading contract and the life cycle.
 */
public abstract non-sealed class SensorActuatorMethod extends Method {

    protected SensorActuatorMethod() {
    }

    @Override
    public final Layer layer() {
        return Layer.SENSORS_ACTUATORS;
    }
}
