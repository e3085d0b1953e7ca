package org.habla.methods.virtual;

import java.time.Duration;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.methods.perception.NearestObstacle;
import org.habla.methods.position.TargetPosition;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The distance-angle method, type {@code distance-angle}: where the target is, for the control
 * architecture, as {@code {"distanceM", "angleRad", "seen"}} in the robot frame (angle positive to the
 * left) at a steady {@code rateHz}. It reads either a {@code nearest} record (from {@code nearest-distance},
 * the nearest thing the range sensors see) or a {@code position} record (from {@code coordinate-translation},
 * the target the camera sees); whichever is wired. While the target is not perceived — the input says so,
 * or nothing fresh came for {@code lostAfterMs} — {@code seen} is false and the distance and angle are those
 * of the last sighting (zero before the first). Nothing is emitted before the first input arrives.
 */
public final class DistanceAngle extends VirtualMethod {

    private static final InputPort<RecordValue> NEAREST = InputPort.optional("nearest", RecordValue.class,
            Delivery.latest());
    private static final InputPort<RecordValue> POSITION = InputPort.optional("position", RecordValue.class,
            Delivery.latest());
    private static final OutputPort<RecordValue> DISTANCE_ANGLE = OutputPort.of("distance_angle", RecordValue.class,
            Shape.record("the target in the robot frame: distance (m), bearing (rad, + left), whether it is perceived",
                    TargetBearing.LAYOUT));
    static final Ports PORTS = Ports.of(NEAREST, POSITION, DISTANCE_ANGLE);

    private final DistanceAngleParams params;
    private final Output<RecordValue> out = output(DISTANCE_ANGLE);

    private boolean started;
    private boolean seen;
    private double distanceM;
    private double angleRad;
    private long lastSeenMicros;
    private long lastSourceMicros;
    private long malformed;

    DistanceAngle(DistanceAngleParams params) {
        this.params = params;
        input(NEAREST, this::onNearest);
        input(POSITION, this::onPosition);
        tickEvery(Duration.ofNanos(Math.round(1e9 / params.rateHz())));
    }

    private void onNearest(RecordValue value, Sample sample) {
        NearestObstacle n = NearestObstacle.fromRecord(value);
        update(n.valid(), n.distanceM(), n.angleRad(), value, sample);
    }

    private void onPosition(RecordValue value, Sample sample) {
        TargetPosition p = TargetPosition.fromRecord(value);
        update(p.seen(), p.distanceM(), p.angleRad(), value, sample);
    }

    private void update(boolean perceived, double d, double a, RecordValue value, Sample sample) {
        started = true;
        lastSourceMicros = sample.sourceMicros();
        if (!perceived) {
            seen = false;
            return;
        }
        if (!Double.isFinite(d) || !Double.isFinite(a) || d < 0) {
            if (malformed++ == 0) {
                log().warn("{}: a record without finite distanceM >= 0 and angleRad was ignored: {}", id(), value);
            }
            return;
        }
        seen = true;
        distanceM = d;
        angleRad = a;
        lastSeenMicros = nowMicros();
    }

    @Override
    protected void onTick(long nowMicros) {
        if (!started) {
            return;
        }
        if (seen && nowMicros - lastSeenMicros > params.lostAfterMs() * 1000L) {
            seen = false;
        }
        emit(out, RecordValue.of(new TargetBearing(distanceM, angleRad, seen)), lastSourceMicros);
    }

    /** Input records that lacked a finite distance or angle, since start. */
    public long malformed() {
        return malformed;
    }

    /** Makes {@code distance-angle} methods. */
    public static final class Provider extends SimpleMethodProvider<DistanceAngleParams> {
        public Provider() {
            super("distance-angle", "The target's distance and bearing with a seen flag, at a steady rate",
                    DistanceAngleParams.class, PORTS, (layer, p) -> new DistanceAngle(p), Layer.VIRTUAL);
        }
    }
}
