package org.habla.method.builtin;

import org.habla.method.Layer;
import org.habla.method.Method;
import org.habla.method.Output;
import org.habla.method.ProcessingMethod;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.VirtualMethod;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.Payload;

/**
 * The paper's "trivial" method, type {@code pass-through}: it hands every sample of its input {@code in}
 * unchanged to its output {@code out}, keeping the source time. It lets raw data climb a layer where
 * no processing is needed, and carries actions down to an actuator channel. It can sit in any layer,
 * so there is one small class per layer base.
 */
public final class PassThrough {

    private PassThrough() {
    }

    /** Makes a pass-through method for {@code layer}. */
    public static Method create(Layer layer, RelayParams params) {
        return switch (layer) {
            case SENSORS_ACTUATORS -> new Sensing(params);
            case PROCESSING -> new Processing(params);
            case VIRTUAL -> new Virtual(params);
        };
    }

    /** A pass-through in the sensors &amp; actuators layer. */
    public static final class Sensing extends SensorActuatorMethod {
        Sensing(RelayParams params) {
            relay(RelayPorts.of(params));
        }

        private <P extends Payload> void relay(RelayPorts<P> ports) {
            Output<P> out = output(ports.out());
            input(ports.in(), (value, sample) -> emit(out, value));
        }
    }

    /** A pass-through in the processing layer. */
    public static final class Processing extends ProcessingMethod {
        Processing(RelayParams params) {
            relay(RelayPorts.of(params));
        }

        private <P extends Payload> void relay(RelayPorts<P> ports) {
            Output<P> out = output(ports.out());
            input(ports.in(), (value, sample) -> emit(out, value));
        }
    }

    /** A pass-through in the virtual information layer. */
    public static final class Virtual extends VirtualMethod {
        Virtual(RelayParams params) {
            relay(RelayPorts.of(params));
        }

        private <P extends Payload> void relay(RelayPorts<P> ports) {
            Output<P> out = output(ports.out());
            input(ports.in(), (value, sample) -> emit(out, value));
        }
    }

    /** Makes {@code pass-through} methods, in any layer. */
    public static final class Provider extends SimpleMethodProvider<RelayParams> {
        public Provider() {
            super("pass-through", "Hands every sample on unchanged (the trivial method of any layer)",
                    RelayParams.class, RelayPorts::ports, PassThrough::create,
                    Layer.SENSORS_ACTUATORS, Layer.PROCESSING, Layer.VIRTUAL);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
