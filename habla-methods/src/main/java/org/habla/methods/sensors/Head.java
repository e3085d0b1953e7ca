package org.habla.methods.sensors;

import org.habla.driver.ChannelDescriptor;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.methods.gaze.HeadLimits;
import org.habla.methods.gaze.HeadPose;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.VectorValue;

/**
 * The general head method, type {@code head}: it reads where a pan-and-tilt head points and moves it.
 * Input {@code pose} takes the head's angles as the record {@code {"tiltRad","panRad","nodRad"}} and
 * output {@code pose} hands on every well-formed reading. Input {@code command} takes the vector
 * {@code [tiltRad, panRad, nodRad]} (nod may be left out) and output {@code head}, listed under the
 * config's {@code commands}, sends it with each angle clamped to its joint's limits. Limits come from
 * params, else from the pose channel's metadata ({@code tiltMinRad}, {@code tiltMaxRad}, …), else
 * from a Sony ERS-7. Either input may be left unwired.
 */
public final class Head extends SensorActuatorMethod {

    private static final OutputPort<RecordValue> POSE_OUT = OutputPort.of("pose", RecordValue.class,
            Shape.record("where the head points, rad", HeadPose.LAYOUT));
    private static final OutputPort<VectorValue> HEAD = OutputPort.of("head", VectorValue.class,
            Shape.vector("rad", "[tiltRad, panRad, nodRad] within the joint limits"));
    private static final InputPort<RecordValue> POSE_IN = InputPort.optional("pose", RecordValue.class,
            Delivery.latest());
    private static final InputPort<VectorValue> COMMAND = InputPort.optional("command", VectorValue.class,
            Delivery.queue(8));
    static final Ports PORTS = Ports.of(POSE_OUT, HEAD, POSE_IN, COMMAND);

    private final HeadParams params;
    private final Output<RecordValue> poseOut = output(POSE_OUT);
    private final Output<VectorValue> headOut = output(HEAD);
    private final Input<RecordValue> pose = input(POSE_IN, this::onPose);

    private HeadLimits limits;
    private long rejected;

    Head(HeadParams params) {
        this.params = params;
        input(COMMAND, this::onCommand);
    }

    @Override
    protected void onStart() {
        limits = HeadLimits.resolve(params, channelOf(pose).map(ChannelDescriptor::metadata).orElse(null));
    }

    private void onPose(RecordValue record, Sample sample) {
        HeadPose.fromRecord(record).ifPresentOrElse(p -> emit(poseOut, p.toRecord()), () -> rejected++);
    }

    private void onCommand(VectorValue command, Sample sample) {
        HeadPose wanted = HeadPose.fromVector(command).orElse(null);
        if (wanted == null) {
            rejected++;
            if (rejected == 1 || rejected % 1000 == 0) {
                log().warn("{}: head command {} is not [tilt, pan, nod] of finite numbers; ignored ({} so far)", id(),
                        command, rejected);
            }
            return;
        }
        emit(headOut, limits.clamp(wanted).toVector());
    }

    /** The limits in force (after start). */
    public HeadLimits limits() {
        return limits;
    }

    /** Readings and commands that were malformed, since start. */
    public long rejected() {
        return rejected;
    }

    /** Makes {@code head} methods. */
    public static final class Provider extends SimpleMethodProvider<HeadParams> {
        public Provider() {
            super("head", "Reads a pan-and-tilt head's pose and sends head commands clamped to its joint limits",
                    HeadParams.class, PORTS, (layer, p) -> new Head(p), Layer.SENSORS_ACTUATORS);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
