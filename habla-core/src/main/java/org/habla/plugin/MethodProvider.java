package org.habla.plugin;

import java.util.Set;
import org.habla.method.Layer;
import org.habla.method.Method;

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

    /** A new method for {@code layer} (one of {@link #layers()}) with validated params. Cheap: no I/O. */
    Method create(Layer layer, P params);
}
