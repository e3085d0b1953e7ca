package org.habla.method.builtin;

import org.habla.method.Input;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.SensorActuatorMethod;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.Payload;

/**
 * The trivial sensor method, type {@code channel}: it stores the readings of one interface channel
 * (input {@code in}) and hands them unchanged to the processing layer (output {@code out}). Its
 * actuator counterpart is a {@code pass-through} whose output is listed under {@code commands}.
 */
public final class ChannelReader extends SensorActuatorMethod {

    private final Input<?> in;

    public ChannelReader(RelayParams params) {
        this.in = relay(RelayPorts.of(params));
    }

    private <P extends Payload> Input<P> relay(RelayPorts<P> ports) {
        Output<P> out = output(ports.out());
        return input(ports.in(), (value, sample) -> emit(out, value));
    }

    @Override
    protected void onStart() {
        if (channelOf(in).isEmpty()) {
            log().warn("{}: input 'in' is not wired to an interface channel; use pass-through for method outputs", id());
        }
    }

    /** Makes {@code channel} methods. */
    public static final class Provider extends SimpleMethodProvider<RelayParams> {
        public Provider() {
            super("channel", "Hands the readings of one interface channel to the processing layer unchanged",
                    RelayParams.class, RelayPorts::ports, (layer, p) -> new ChannelReader(p), Layer.SENSORS_ACTUATORS);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
