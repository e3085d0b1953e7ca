package org.habla.methods.motion;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.VectorValue;

/**
 * The motion-composition method, type {@code motion-composition}: turns the high-level motion asked for
 * (input {@code motion}, {@code [vMps, wRadps]}) into the motion a differential base can follow (output
 * {@code motion}). The wanted motion is first brought within the top speeds — params, else the optional
 * {@code limits} input (e.g. from {@code wheels}) — keeping its curvature; then, every {@code tickMs}, the
 * output moves towards it by no more than the acceleration limits allow ({@code maxAccelMps2} speeding up,
 * {@code maxDecelMps2} braking, {@code maxRotAccelRadps2} for the turn rate). A change of direction brakes
 * to zero first. The output is emitted on each step while it changes and is silent when steady. When the
 * engine stops the robot (the motion watchdog), the ramp starts again from rest: the next motion asked for is
 * ramped up from zero and sent, even if it is the one sent last before the stop.
 */
public final class MotionComposition extends ProcessingMethod {

    private static final InputPort<VectorValue> MOTION = InputPort.of("motion", VectorValue.class, Delivery.latest());
    private static final InputPort<RecordValue> LIMITS = InputPort.optional("limits", RecordValue.class,
            Delivery.latest());
    /** The ramped motion (the input of the same name is the one asked for). */
    private static final OutputPort<VectorValue> OUT = OutputPort.of("motion", VectorValue.class,
            new Shape(PayloadKind.VECTOR, "m/s, rad/s", List.of("vMps", "wRadps"),
                    "the motion for the base, within its top speeds and acceleration"));
    static final Ports PORTS = Ports.of(MOTION, LIMITS, OUT);

    private final MotionCompositionParams params;
    private final Output<VectorValue> out = output(OUT);

    private MotionLimits limits;
    private double targetV;
    private double targetW;
    private double v;
    private double w;
    private boolean settled = true;
    private long lastStepMicros;
    private long malformed;

    MotionComposition(MotionCompositionParams params) {
        this.params = params;
        this.limits = MotionLimits.NONE.overriddenBy(params.maxVelMps(), params.maxRotVelRadps());
        input(MOTION, this::onMotion);
        input(LIMITS, this::onLimits);
        tickEvery(Duration.ofMillis(params.tickMs()));
    }

    private void onLimits(RecordValue value, Sample sample) {
        limits = MotionLimits.fromRecord(value)
                .overriddenBy(params.maxVelMps(), params.maxRotVelRadps());
        setTarget(targetV, targetW);
    }

    private void onMotion(VectorValue value, Sample sample) {
        Optional<double[]> m = MotionLimits.motionOf(value);
        if (m.isEmpty()) {
            if (malformed++ == 0) {
                log().warn("{}: a motion that is not [vMps, wRadps] of finite numbers is taken as zero: {}", id(), value);
            }
            setTarget(0, 0);
        } else {
            setTarget(m.get()[0], m.get()[1]);
        }
        if (settled) {
            return;
        }
        long now = nowMicros();
        if (now - lastStepMicros >= params.tickMs() * 1000L) {
            step(now);
        }
    }

    private void setTarget(double vMps, double wRadps) {
        double[] clamped = limits.clamp(vMps, wRadps);
        targetV = clamped[0];
        targetW = clamped[1];
        settled = targetV == v && targetW == w;
    }

    @Override
    protected void onTick(long nowMicros) {
        if (!settled) {
            step(nowMicros);
        }
    }

    private void step(long nowMicros) {
        double dt = params.tickMs() / 1000.0;
        v = approachV(v, targetV, dt);
        w = approach(w, targetW, params.maxRotAccelRadps2() * dt);
        lastStepMicros = nowMicros;
        settled = v == targetV && w == targetW;
        emit(out, VectorValue.of(v, w));
    }

    private double approachV(double current, double target, double dt) {
        boolean reversing = current != 0 && Math.signum(target) != Math.signum(current);
        if (reversing || Math.abs(target) < Math.abs(current)) {
            double goal = reversing ? 0 : target;
            return approach(current, goal, params.maxDecelMps2() * dt);
        }
        return approach(current, target, params.maxAccelMps2() * dt);
    }

    private static double approach(double current, double target, double maxStep) {
        double d = target - current;
        // a hair of slack, so rounding never leaves a last step of 1e-17
        return Math.abs(d) <= maxStep * (1 + 1e-9) ? target : current + Math.signum(d) * maxStep;
    }

    @Override
    protected void onMotionStopped() {
        v = 0;
        w = 0;
        targetV = 0;
        targetW = 0;
        settled = true;
    }

    /** Motions that were not two finite numbers, since start. */
    public long malformed() {
        return malformed;
    }

    /** Makes {@code motion-composition} methods. */
    public static final class Provider extends SimpleMethodProvider<MotionCompositionParams> {
        public Provider() {
            super("motion-composition", "Ramps [v, w] motions within a base's top speeds and acceleration limits",
                    MotionCompositionParams.class, PORTS, (layer, p) -> new MotionComposition(p), Layer.PROCESSING);
        }
    }
}
