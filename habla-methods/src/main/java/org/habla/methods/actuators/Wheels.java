package org.habla.methods.actuators;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.methods.motion.MotionLimits;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.VectorValue;

/**
 * The wheels method, type {@code wheels}: the actuator of a differential base. Input {@code motion}
 * {@code [vMps, wRadps]} (turn rate positive counter-clockwise) goes out on output {@code motion}, which
 * the config writes to the robot's motion channel ({@code "commands": {"motion": "@robot.motion"}}). A
 * motion beyond the base's top speeds is scaled down, keeping its curvature; the limits come from the
 * command channel's metadata ({@code maxVelMps}, {@code maxRotVelRadps}) or from params. A vector that is
 * not two finite numbers is answered with zero (the safe motion) and counted. When the method stops it
 * sends zero.
 *
 * <p>Output {@code limits} publishes the limits in force, at start and once a second, so processing methods
 * above ({@code motion-composition}, {@code movement-safety}) can learn them without knowing the robot.
 */
public final class Wheels extends SensorActuatorMethod {

    private static final OutputPort<VectorValue> MOTION_OUT = OutputPort.of("motion", VectorValue.class,
            new Shape(PayloadKind.VECTOR, "m/s, rad/s", List.of("vMps", "wRadps"), "the motion sent to the base"));
    private static final OutputPort<RecordValue> LIMITS = OutputPort.of("limits", RecordValue.class,
            Shape.record("the base's top speeds in force", MotionLimits.LAYOUT));
    private static final InputPort<VectorValue> MOTION_IN = InputPort.of("motion", VectorValue.class,
            Delivery.latest());
    static final Ports PORTS = Ports.of(MOTION_OUT, LIMITS, MOTION_IN);

    private final WheelsParams params;
    private final Output<VectorValue> motionOut = output(MOTION_OUT);
    private final Output<RecordValue> limitsOut = output(LIMITS);

    private MotionLimits limits = MotionLimits.NONE;
    private long malformed;

    Wheels(WheelsParams params) {
        this.params = params;
        input(MOTION_IN, this::onMotion);
        tickEvery(Duration.ofSeconds(1));
    }

    @Override
    protected void onStart() {
        Optional<ChannelDescriptor> channel = commandChannelOf(motionOut);
        limits = channel.flatMap(c -> MotionLimits.fromJson(c.metadata())).orElse(MotionLimits.NONE)
                .overriddenBy(params.maxVelMps(), params.maxRotVelRadps());
        if (limits.equals(MotionLimits.NONE)) {
            log().info("{}: no speed limits from params or the motion channel; motions are sent unscaled", id());
        }
        emit(limitsOut, limits.toRecord());
    }

    private void onMotion(VectorValue value, Sample sample) {
        Optional<double[]> motion = MotionLimits.motionOf(value);
        if (motion.isEmpty()) {
            if (malformed++ == 0) {
                log().warn("{}: a motion that is not [vMps, wRadps] of finite numbers was answered with zero: {}",
                        id(), value);
            }
            send(0, 0);
            return;
        }
        double[] vw = limits.clamp(motion.get()[0], motion.get()[1]);
        send(vw[0], vw[1]);
    }

    private void send(double v, double w) {
        emit(motionOut, VectorValue.of(v, w));
    }

    @Override
    protected void onTick(long nowMicros) {
        emit(limitsOut, limits.toRecord());
    }

    @Override
    protected void onStop() {
        send(0, 0);
    }

    /** The limits in force (after start). */
    public MotionLimits limits() {
        return limits;
    }

    /** Motions that were not two finite numbers, since start. */
    public long malformed() {
        return malformed;
    }

    /** Makes {@code wheels} methods. */
    public static final class Provider extends SimpleMethodProvider<WheelsParams> {
        public Provider() {
            super("wheels", "Sends [v, w] motions to a differential base, within its top speeds; zero on stop",
                    WheelsParams.class, PORTS, (layer, p) -> new Wheels(p), Layer.SENSORS_ACTUATORS);
        }
    }
}
