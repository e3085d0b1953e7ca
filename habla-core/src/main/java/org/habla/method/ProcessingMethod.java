package org.habla.method;

/**
 * Base of every method of the processing layer: general signal processing shared by several high-level methods, and composition of commands.
 * See {@link Method} for the threading contract and the life cycle.
 */
public abstract non-sealed class ProcessingMethod extends Method {

    protected ProcessingMethod() {
    }

    @Override
    public final Layer layer() {
        return Layer.PROCESSING;
    }
}
