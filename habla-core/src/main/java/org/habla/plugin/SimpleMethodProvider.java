package org.habla.plugin;

import java.util.EnumSet;
import java.util.Objects;
import java.util.Set;
import java.util.function.BiFunction;
import java.util.function.Function;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Ports;

/**
 * A method provider made of its parts: a name, a sentence, the params record, the ports, a factory and the
 * layers. A concrete provider is a subclass with a public no-argument constructor (so
 * {@link java.util.ServiceLoader} can make it) that passes those parts up:
 *
 * <pre>{@code
 * public static final class Provider extends SimpleMethodProvider<SonarParams> {
 *     public Provider() {
 *         super("sonar", "Validated sonar ranges and scan geometry", SonarParams.class,
 *                 Sonar.PORTS, (layer, p) -> new Sonar(p), Layer.SENSORS_ACTUATORS);
 *     }
 * }
 * }</pre>
 *
 * A type whose ports follow its params passes the function that lists them ({@code RoomAction::ports})
 * instead of one {@link Ports}.
 *
 * @param <P> the params record
 */
public abstract class SimpleMethodProvider<P extends Record> implements MethodProvider<P> {

    private final String name;
    private final String description;
    private final Class<P> paramsType;
    private final Function<P, Ports> ports;
    private final BiFunction<Layer, P, Method> factory;
    private final Set<Layer> layers;

    /** A type whose ports are the same whatever its params. */
    protected SimpleMethodProvider(String name, String description, Class<P> paramsType, Ports ports,
            BiFunction<Layer, P, Method> factory, Layer first, Layer... more) {
        this(name, description, paramsType, fixed(ports), factory, first, more);
    }

    /** A type whose ports follow its params. */
    protected SimpleMethodProvider(String name, String description, Class<P> paramsType, Function<P, Ports> ports,
            BiFunction<Layer, P, Method> factory, Layer first, Layer... more) {
        this.name = Objects.requireNonNull(name, "name");
        this.description = Objects.requireNonNull(description, "description");
        this.paramsType = Objects.requireNonNull(paramsType, "paramsType");
        this.ports = Objects.requireNonNull(ports, "ports");
        this.factory = Objects.requireNonNull(factory, "factory");
        this.layers = Set.copyOf(EnumSet.of(first, more));
    }

    private static <P> Function<P, Ports> fixed(Ports ports) {
        Objects.requireNonNull(ports, "ports");
        return p -> ports;
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
    public final Ports ports(Layer layer, P params) {
        placeable(layer);
        return ports.apply(Objects.requireNonNull(params, "params"));
    }

    @Override
    public final Method create(Layer layer, P params) {
        placeable(layer);
        Method m = factory.apply(layer, Objects.requireNonNull(params, "params"));
        if (m.layer() != layer) {
            throw new IllegalStateException("method type '" + name + "' made a " + m.layer() + " method for " + layer);
        }
        return m;
    }

    private void placeable(Layer layer) {
        if (!layers.contains(layer)) {
            throw new IllegalArgumentException("method type '" + name + "' cannot be placed in the "
                    + layer.configName() + " layer; it belongs in " + layers.stream().map(Layer::configName).sorted().toList());
        }
    }

    @Override
    public String toString() {
        return "method type " + name;
    }
}
