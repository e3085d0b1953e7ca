package org.habla.config;

import java.util.Set;
import java.util.function.BiFunction;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.plugin.MethodProvider;

/** A method provider for tests, made from a name, its layers, its params record and a factory. */
record TestProvider<P extends Record>(String name, Set<Layer> layers, Class<P> paramsType,
        BiFunction<Layer, P, Method> factory) implements MethodProvider<P> {

    @Override
    public String description() {
        return "test type " + name;
    }

    @Override
    public org.habla.method.Ports ports(Layer layer, P params) {
        return create(layer, params).boundPorts();
    }

    @Override
    public Method create(Layer layer, P params) {
        return factory.apply(layer, params);
    }
}
