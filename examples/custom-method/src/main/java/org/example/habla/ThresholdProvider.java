package org.example.habla;

import java.util.Set;
import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Ports;
import org.habla.plugin.MethodProvider;

/** Registers {@link Threshold} under the type name {@code threshold}. */
public final class ThresholdProvider implements MethodProvider<ThresholdParams> {

    @Override
    public String name() {
        return "threshold";
    }

    @Override
    public String description() {
        return "Labels the nearest obstacle near or far, with hysteresis";
    }

    @Override
    public Set<Layer> layers() {
        return Set.of(Layer.PROCESSING);
    }

    @Override
    public Class<ThresholdParams> paramsType() {
        return ThresholdParams.class;
    }

    @Override
    public Ports ports(Layer layer, ThresholdParams params) {
        return Threshold.PORTS;
    }

    @Override
    public Method create(Layer layer, ThresholdParams params) {
        return new Threshold(params);
    }
}
