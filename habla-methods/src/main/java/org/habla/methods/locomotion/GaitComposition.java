package org.habla.methods.locomotion;

import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.Sample;
import org.habla.sample.VectorValue;

/**
 * The gait composition method, type {@code gait-composition}: it turns the planar motion a wheeled
 * robot would be given, input {@code motion} = {@code [vMps, wRadps]}, into the walk command of a
 * legged robot, output {@code walk} = {@code [forwardMps, strafeMps, rotateRadps]}, so the same action
 * method drives both. Speeds are multiplied by {@code forwardScale} and {@code rotateScale}, then
 * shrunk together to the walk limits (keeping the curve the motion asked for). With a
 * {@code strafeShare} above 0 a part of every turn is walked sideways instead, towards the side of
 * the turn; a third element in the motion vector is taken as a sideways speed of its own (m/s, + left).
 * A motion that is not two or three finite numbers stops the walk.
 */
public final class GaitComposition extends ProcessingMethod {

    private static final InputPort<VectorValue> MOTION = InputPort.of("motion", VectorValue.class, Delivery.queue(8));
    private static final OutputPort<VectorValue> WALK = OutputPort.of("walk", VectorValue.class,
            Shape.vector("m/s, rad/s", "[forwardMps, strafeMps, rotateRadps] within the walk limits"));
    static final Ports PORTS = Ports.of(MOTION, WALK);

    private final GaitCompositionParams params;
    private final WalkLimits limits;
    private final Output<VectorValue> walk = output(WALK);
    private long rejected;

    GaitComposition(GaitCompositionParams params) {
        this.params = params;
        this.limits = params.limits();
        input(MOTION, this::onMotion);
    }

    private void onMotion(VectorValue motion, Sample sample) {
        int n = motion.size();
        double[] m = motion.toArray();
        boolean valid = (n == 2 || n == 3);
        for (int i = 0; valid && i < n; i++) {
            valid = Double.isFinite(m[i]);
        }
        if (!valid) {
            rejected++;
            if (rejected == 1 || rejected % 1000 == 0) {
                log().warn("{}: motion {} is not [vMps, wRadps] of finite numbers; walking stops ({} so far)", id(),
                        motion, rejected);
            }
            emit(walk, VectorValue.of(0, 0, 0));
            return;
        }
        double forward = m[0] * params.forwardScale();
        double turn = m[1] * params.rotateScale();
        double strafe = (n == 3 ? m[2] : 0) + turn * params.strafeShare() * params.strafeMpsPerRadps();
        double rotate = turn * (1 - params.strafeShare());
        emit(walk, VectorValue.wrap(limits.scale(forward, strafe, rotate)));
    }

    /** Motions that were not valid vectors, since start. */
    public long rejected() {
        return rejected;
    }

    /** Makes {@code gait-composition} methods. */
    public static final class Provider extends SimpleMethodProvider<GaitCompositionParams> {
        public Provider() {
            super("gait-composition", "Turns a planar motion [v, w] into a walk [forward, strafe, rotate] within the walk limits",
                    GaitCompositionParams.class, PORTS, (layer, p) -> new GaitComposition(p), Layer.PROCESSING);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
