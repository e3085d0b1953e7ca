package org.habla.methods.sensors;

import org.habla.driver.ChannelDescriptor;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.methods.locomotion.WalkLimits;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.Sample;
import org.habla.sample.VectorValue;

/**
 * The general legs method, type {@code legs}: it sends walk commands to a legged robot. Input
 * {@code walk} takes the vector {@code [forwardMps, strafeMps, rotateRadps]} (or {@code [forwardMps,
 * rotateRadps]}); output {@code walk}, listed under the config's {@code commands}, carries it to the
 * interface's walk channel with each component clamped to its limit: from params, else from the walk
 * channel's metadata ({@code maxForwardMps}, {@code maxReverseMps}, {@code maxStrafeMps},
 * {@code maxRotateRadps}), else a Sony ERS-7's. A command that is not such a
 * vector (a wrong length, a NaN) stops the robot rather than being guessed at, and when the method stops
 * it sends a last zero command so the robot never walks on unattended.
 */
public final class Legs extends SensorActuatorMethod {

    private static final VectorValue HALT = VectorValue.of(0, 0, 0);
    private static final OutputPort<VectorValue> WALK_OUT = OutputPort.of("walk", VectorValue.class,
            Shape.vector("m/s, rad/s", "[forwardMps, strafeMps, rotateRadps] within the walk limits"));

    private final LegsParams params;
    private WalkLimits limits;
    private final Output<VectorValue> walk = output(WALK_OUT);
    private long rejected;
    private boolean sentAny;

    Legs(LegsParams params) {
        this.params = params;
        input(walkIn(params.queue()), this::onWalk);
    }

    /** The ports of legs with these params: the walk input queues {@code queue} commands. */
    static Ports ports(LegsParams params) {
        return Ports.of(WALK_OUT, walkIn(params.queue()));
    }

    private static InputPort<VectorValue> walkIn(int queue) {
        return InputPort.of("walk", VectorValue.class, Delivery.queue(queue));
    }

    @Override
    protected void onStart() {
        limits = params.limits(commandChannelOf(walk).map(ChannelDescriptor::metadata).orElse(null));
    }

    /** The limits in force (after start). */
    public WalkLimits limits() {
        return limits;
    }

    private void onWalk(VectorValue value, Sample sample) {
        double[] cmd = WalkLimits.read(value).orElse(null);
        sentAny = true;
        if (cmd == null) {
            rejected++;
            if (rejected == 1 || rejected % 1000 == 0) {
                log().warn("{}: walk command {} is not [forward, strafe, rotate] of finite numbers; stopping instead "
                        + "({} so far)", id(), value, rejected);
            }
            emit(walk, HALT);
            return;
        }
        emit(walk, VectorValue.wrap(limits.clamp(cmd[0], cmd[1], cmd[2])));
    }

    @Override
    protected void onStop() {
        if (sentAny) {
            emit(walk, HALT);
        }
    }

    /** Walk commands that were not valid vectors (each stopped the robot), since start. */
    public long rejected() {
        return rejected;
    }

    /** Makes {@code legs} methods. */
    public static final class Provider extends SimpleMethodProvider<LegsParams> {
        public Provider() {
            super("legs", "Sends walk commands [forward, strafe, rotate] to a legged robot, clamped to its walk limits",
                    LegsParams.class, Legs::ports, (layer, p) -> new Legs(p), Layer.SENSORS_ACTUATORS);
        }
    }
}
