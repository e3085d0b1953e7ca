package org.habla.plugin;

import java.util.List;
import java.util.Set;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Ports;

/**
 * Makes methods of one type. Registered through {@code META-INF/services/org.habla.plugin.MethodProvider};
 * a config names the type by {@link #name()}.
 *
 * @param <P> the params record the config's {@code params} object is bound to; its constructor validates
 */
public interface MethodProvider<P extends Record> {

    /** The stable type name used in configs, e.g. {@code "nearest-distance"}. */
    String name();

    /** One sentence on what the method does. */
    String description();

    /** The layers the type can be placed in (most types have exactly one). */
    Set<Layer> layers();

    /** The record the {@code params} object is bound to ({@link NoParams} for none). */
    Class<P> paramsType();

    /**
     * The inputs and outputs a method of this type has for {@code layer} and {@code params}, without making
     * one: the config check wires against them and a graph picture draws them.
     *
     * @throws IllegalArgumentException if the params leave the ports undefined
     */
    Ports ports(Layer layer, P params);

    /**
     * Whether methods of this type are light: each handles a message in microseconds, never blocks (no I/O, no
     * waiting, no sleeping), asks for no ticks and runs no background work. The engine may then run a method of
     * the type on the thread that delivers to it, with the methods after it, instead of on a thread of its own
     * (docs/architecture.md, "Threads"); a method that writes interface commands, runs on a worker, or is fed from
     * more than one thread keeps its own thread whatever its type says. {@link #make} refuses a light type's method
     * that asks for ticks, and the engine fails one that asks for background work. Most types are not: false by
     * default.
     */
    default boolean light() {
        return false;
    }

    /** A new method for {@code layer} (one of {@link #layers()}) with validated params. Cheap: no I/O. */
    Method create(Layer layer, P params);

    /**
     * A new method of {@code provider}'s type, checked: it is of {@code layer} and binds exactly the ports
     * the type lists for these params. The engine makes every method through here.
     *
     * @throws IllegalStateException if the method made is of another layer or binds other ports, or is of a
     *                               {@link #light} type and asks for ticks
     */
    static <P extends Record> Method make(MethodProvider<P> provider, Layer layer, Record params) {
        P p = provider.paramsType().cast(params);
        Method made = provider.create(layer, p);
        if (made.layer() != layer) {
            throw new IllegalStateException("method type '" + provider.name() + "' made a " + made.layer().configName()
                    + " method when asked for the " + layer.configName() + " layer");
        }
        List<String> differences = provider.ports(layer, p).differences(made.boundPorts());
        if (!differences.isEmpty()) {
            throw new IllegalStateException("method type '" + provider.name() + "' made a method whose ports are"
                    + " not the ones it lists: " + String.join("; ", differences));
        }
        if (provider.light() && made.tickPeriod().isPresent()) {
            throw new IllegalStateException("method type '" + provider.name() + "' is light, so its methods run on"
                    + " the thread that delivers to them, and cannot ask for ticks; declare it not light");
        }
        return made;
    }
}
