package org.habla.plugin;

import java.util.EnumSet;
import java.util.Objects;
import java.util.Set;
import java.util.function.BiFunction;
import org.habla.method.Layer;
import org.habla.method.Method;

/**
 * A method provider made of its parts: a name, a sentence, the layers and a factory. A concrete
 * provider is a subclass with a public no-argument constructor (so {@link java.util.ServiceLoader}
 * can make it) that passes those parts up:
 *
 * <pre>{@code
 * public static final class Provider extends SimpleMethodProvider<SonarParams> {
 *     public Provider() {
 *         super("sonar", "Validated sonar ranges and scan geometry", SonarParams.class,
 *                 (layer, p) -> new Sonar(p), Layer.SENSORS_ACTUATORS);
 *     }
 * }
 * }</pre>
 *
 * @param <P> the params record
 */
public abstract class SimpleMethodProvider<P extends Record> implements MethodProvider<P> {

    private final String name;
    private final String description;
    private final Class<P> paramsType;
    private final BiFunction<Layer, P, Method> factory;
    private final Set<Layer> layers;

    protected SimpleMethodProvider(String name, String description, Class<P> paramsType,
            BiFunction<Layer, P, Method> factory, Layer first, Layer... more) {
        this.name = Objects.requireNonNull(name, "name");
        this.description = Objects.requireNonNull(description, "description");
        this.paramsType = Objects.requireNonNull(paramsType, "paramsType");
        this.factory = Objects.requireNonNull(factory, "factory");
        this.layers = Set.copyOf(EnumSet.of(first, more));
    }

    @Override
    public final String name() {
        return name;
    }

    @Override
    public final String description() {
        return description;
    }

    @Override
    public final Set<Layer> layers() {
        return layers;
    }

    @Override
    public final Class<P> paramsType() {
        return paramsType;
    }

    @Override
    public final Method create(Layer layer, P params) {
        if (!layers.contains(layer)) {
            throw new IllegalArgumentException("method type '" + name + "' cannot be placed in the "
                    + layer.configName() + " layer; it belongs in " + layers.stream().map(Layer::configName).sorted().toList());
        }
        Method m = factory.apply(layer, Objects.requireNonNull(params, "params"));
        if (m.layer() != layer) {
            throw new IllegalStateException("method type '" + name + "' made a " + m.layer() + " method for " + layer);
        }
        return m;
    }

    @Override
    public String toString() {
        return "method type " + name;
    }
}
