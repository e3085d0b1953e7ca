package org.example.habla;

import org.habla.method.Layer;
import org.habla.plugin.SimpleMethodProvider;

/**
 * Registers {@link Threshold} under the type name {@code threshold}, in the processing layer. Public and without
 * arguments, so {@link java.util.ServiceLoader} can make it from the services file.
 */
public final class ThresholdProvider extends SimpleMethodProvider<ThresholdParams> {

    public ThresholdProvider() {
        super("threshold", "Labels the nearest obstacle near or far, with hysteresis", ThresholdParams.class,
                Threshold.PORTS, (layer, params) -> new Threshold(params), Layer.PROCESSING);
    }
}
