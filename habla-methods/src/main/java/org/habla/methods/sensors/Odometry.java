package org.habla.methods.sensors;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import java.util.Optional;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.SensorActuatorMethod;
import org.habla.method.Shape;
import org.habla.methods.geometry.PlanarPose;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.VectorValue;

/**
 * The odometry method, type {@code odometry}: where the base thinks it is. Input {@code odometry} takes a
 * driver's odometry record ({@code xM}, {@code yM}, {@code thetaRad}, and {@code vMps}, {@code wRadps} when
 * the driver knows them); output {@code pose} is the record {@code {"xM","yM","thetaRad"}} (heading in
 * (-π, π]) and output {@code velocity} the vector {@code [vMps, wRadps]}. With {@code fromFirstReading} the
 * pose is measured from where the robot stood at the first reading. A record without a finite pose is
 * counted and ignored.
 */
public final class Odometry extends SensorActuatorMethod {

    private static final OutputPort<RecordValue> POSE = OutputPort.of("pose", RecordValue.class,
            Shape.record("the base's pose by odometry, in its odometry frame", PlanarPose.LAYOUT));
    private static final OutputPort<VectorValue> VELOCITY = OutputPort.of("velocity", VectorValue.class,
            new Shape(PayloadKind.VECTOR, "m/s, rad/s", List.of("vMps", "wRadps"), "the base's speed and turn rate"));
    private static final InputPort<RecordValue> ODOMETRY = InputPort.of("odometry", RecordValue.class,
            Delivery.latest());
    static final Ports PORTS = Ports.of(POSE, VELOCITY, ODOMETRY);

    private final OdometryParams params;
    private final Output<RecordValue> poseOut = output(POSE);
    private final Output<VectorValue> velocityOut = output(VELOCITY);

    private PlanarPose origin;
    private long malformed;

    Odometry(OdometryParams params) {
        this.params = params;
        input(ODOMETRY, this::onOdometry);
    }

    private void onOdometry(RecordValue value, Sample sample) {
        Optional<PlanarPose> read = PlanarPose.fromRecord(value);
        if (read.isEmpty()) {
            if (malformed++ == 0) {
                log().warn("{}: an odometry record without finite xM, yM, thetaRad was ignored: {}", id(), value);
            }
            return;
        }
        PlanarPose pose = read.get();
        if (params.fromFirstReading()) {
            if (origin == null) {
                origin = pose;
            }
            pose = relative(origin, pose);
        }
        emit(poseOut, pose.toRecord());
        double v = finite(value.get("vMps"));
        double w = finite(value.get("wRadps"));
        if (!Double.isNaN(v) && !Double.isNaN(w)) {
            emit(velocityOut, VectorValue.of(v, w));
        }
    }

    /** {@code pose} seen from {@code origin}. */
    static PlanarPose relative(PlanarPose origin, PlanarPose pose) {
        double dx = pose.xM() - origin.xM();
        double dy = pose.yM() - origin.yM();
        double c = Math.cos(origin.thetaRad());
        double s = Math.sin(origin.thetaRad());
        return new PlanarPose(c * dx + s * dy, -s * dx + c * dy, pose.thetaRad() - origin.thetaRad());
    }

    /** Records without a finite pose, since start. */
    public long malformed() {
        return malformed;
    }

    private static double finite(JsonNode n) {
        return n.isNumber() && Double.isFinite(n.doubleValue()) ? n.doubleValue() : Double.NaN;
    }

    /** Makes {@code odometry} methods. */
    public static final class Provider extends SimpleMethodProvider<OdometryParams> {
        public Provider() {
            super("odometry", "The base's pose and velocity from a driver's odometry record",
                    OdometryParams.class, PORTS, (layer, p) -> new Odometry(p), Layer.SENSORS_ACTUATORS);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
