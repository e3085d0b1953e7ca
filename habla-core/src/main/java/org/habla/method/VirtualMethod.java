package org.habla.method;

/**
 * Base of every method of the virtual information layer: high-level information and actions, the only layer a control architecture talks to.
 * See {@link Method} for the threading contract and the life cycle.
 */
public abstract non-sealed class VirtualMethod extends Method {

    protected VirtualMethod() {
    }

    @Override
    public final Layer layer() {
        return Layer.VIRTUAL;
    }
}
