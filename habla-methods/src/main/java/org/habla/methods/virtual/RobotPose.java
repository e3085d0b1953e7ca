package org.habla.methods.virtual;

import java.util.Optional;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.methods.geometry.PlanarPose;
import org.habla.plugin.NoParams;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The robot-pose method, type {@code robot-pose}: the robot's pose for the control architecture, as the
 * record {@code {"xM","yM","thetaRad"}} (heading in (-π, π], counter-clockwise). Input {@code pose} takes a
 * pose record, e.g. the {@code odometry} method's; extra fields are left out and a record without a finite
 * pose is counted and ignored.
 */
public final class RobotPose extends VirtualMethod {

    private static final InputPort<RecordValue> POSE_IN = InputPort.of("pose", RecordValue.class, Delivery.latest());
    private static final OutputPort<RecordValue> POSE = OutputPort.of("pose", RecordValue.class,
            Shape.record("the robot's pose: position (m) and heading (rad, counter-clockwise)", PlanarPose.LAYOUT));
    static final Ports PORTS = Ports.of(POSE_IN, POSE);

    private final Output<RecordValue> out = output(POSE);

    private long malformed;

    RobotPose() {
        input(POSE_IN, this::onPose);
    }

    private void onPose(RecordValue value, Sample sample) {
        Optional<PlanarPose> pose = PlanarPose.fromRecord(value);
        if (pose.isEmpty()) {
            if (malformed++ == 0) {
                log().warn("{}: a pose record without finite xM, yM, thetaRad was ignored: {}", id(), value);
            }
            return;
        }
        emit(out, pose.get().toRecord());
    }

    /** Records without a finite pose, since start. */
    public long malformed() {
        return malformed;
    }

    /** Makes {@code robot-pose} methods. */
    public static final class Provider extends SimpleMethodProvider<NoParams> {
        public Provider() {
            super("robot-pose", "The robot's pose {xM, yM, thetaRad} for the control architecture",
                    NoParams.class, PORTS, (layer, p) -> new RobotPose(), Layer.VIRTUAL);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
