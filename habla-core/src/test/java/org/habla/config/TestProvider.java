package org.habla.config;

import java.util.Set;
import java.util.function.BiFunction;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Ports;
import org.habla.plugin.MethodProvider;

/** A method provider for tests, made from a name, its layers, its params record, its ports and a factory. */
record TestProvider<P extends Record>(String name, Set<Layer> layers, Class<P> paramsType,
        BiFunction<Layer, P, Ports> portsOf, BiFunction<Layer, P, Method> factory) implements MethodProvider<P> {

    TestProvider(String name, Set<Layer> layers, Class<P> paramsType, Ports ports, BiFunction<Layer, P, Method> factory) {
        this(name, layers, paramsType, (l, p) -> ports, factory);
    }

    @Override
    public String description() {
        return "test type " + name;
    }

    @Override
    public Ports ports(Layer layer, P params) {
        return portsOf.apply(layer, params);
    }

    @Override
    public Method create(Layer layer, P params) {
        return factory.apply(layer, params);
    }
}
