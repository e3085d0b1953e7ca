package org.habla.methods.perception;

import java.util.List;
import org.habla.method.Delivery;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.Shape;
import org.habla.methods.geometry.PlanarPose;
import org.habla.methods.geometry.RangeScan;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;

/**
 * The nearest-distance method, type {@code nearest-distance}: the nearest thing the range sensors see.
 * It reads one to four {@code scan} records (inputs {@code scan}, {@code scan2}, {@code scan3}, {@code scan4},
 * e.g. sonar and infrared) and, on each new scan, emits the {@code nearest} record ({@link NearestObstacle}):
 * the nearest reading, measured from the sensor that read it, and the obstacle's point and bearing in the robot
 * frame. {@code aheadM} and {@code behindM} are the nearest readings whose bearing is within {@code coneRad} of
 * straight ahead and straight behind, for movement safety. Readings that are not valid (nothing seen) or shorter
 * than {@code minValidM} are ignored; when no reading is left the record says {@code "valid": false},
 * {@code sensor} −1, and the distances are the longest reach. Without sensor poses the bearing is taken as zero
 * (logged once).
 */
public final class NearestDistance extends ProcessingMethod {

    /** The scans: the first must be wired, the other three may be. */
    private static final List<InputPort<RecordValue>> SCANS = List.of(
            InputPort.of("scan", RecordValue.class, Delivery.latest()),
            InputPort.optional("scan2", RecordValue.class, Delivery.latest()),
            InputPort.optional("scan3", RecordValue.class, Delivery.latest()),
            InputPort.optional("scan4", RecordValue.class, Delivery.latest()));
    static final OutputPort<RecordValue> NEAREST = OutputPort.of("nearest", RecordValue.class, Shape.record(
            "the nearest obstacle in the robot frame, and the nearest ahead and behind", NearestObstacle.LAYOUT));
    static final Ports PORTS = Ports.of(NEAREST).plus(SCANS);

    private final NearestDistanceParams params;
    private final Output<RecordValue> nearest = output(NEAREST);
    private final RangeScan[] latest = new RangeScan[SCANS.size()];
    private final long[] receivedMicros = new long[SCANS.size()];

    private long malformed;
    private boolean warnedNoPoses;

    NearestDistance(NearestDistanceParams params) {
        this.params = params;
        for (int i = 0; i < SCANS.size(); i++) {
            int index = i;
            input(SCANS.get(i), (v, s) -> onScan(index, v, s));
        }
    }

    private void onScan(int index, RecordValue value, Sample sample) {
        RangeScan scan;
        try {
            scan = RangeScan.fromRecord(value);
        } catch (IllegalArgumentException e) {
            if (malformed++ == 0) {
                log().warn("{}: a scan on {} was ignored: {}", id(), SCANS.get(index).name(), e.getMessage());
            }
            return;
        }
        long now = nowMicros();
        latest[index] = scan;
        receivedMicros[index] = now;
        Closest best = new Closest();
        Closest ahead = new Closest();
        Closest behind = new Closest();
        double reach = 0;
        for (int i = 0; i < SCANS.size(); i++) {
            RangeScan s = latest[i];
            if (s == null || (i != index && now - receivedMicros[i] > params.maxAgeMs() * 1000L)) {
                continue;
            }
            if (!s.hasPoses() && !warnedNoPoses) {
                warnedNoPoses = true;
                log().warn("{}: the scan on {} carries no sensor poses; bearings are taken as zero", id(), SCANS.get(i).name());
            }
            for (int k = 0; k < s.size(); k++) {
                reach = Math.max(reach, s.maxRangeM(k));
                double r = s.rangeM(k);
                if (!s.valid(k) || r < params.minValidM()) {
                    continue;
                }
                PlanarPose pose = s.pose(k).orElse(PlanarPose.ORIGIN);
                double[] p = pose.pointAt(r, 0);
                double bearing = Math.atan2(p[1], p[0]);
                best.offer(r, p, bearing, k, i);
                if (Math.abs(bearing) <= params.coneRad()) {
                    ahead.offer(r, p, bearing, k, i);
                }
                if (Math.PI - Math.abs(bearing) <= params.coneRad()) {
                    behind.offer(r, p, bearing, k, i);
                }
            }
        }
        if (best.found()) {
            spread(best);
        }
        double aheadM = ahead.found() ? ahead.rangeM : reach;
        double behindM = behind.found() ? behind.rangeM : reach;
        emit(nearest, RecordValue.of(best.found()
                ? new NearestObstacle(best.rangeM, best.bearingRad, best.xM, best.yM, best.sensor,
                        SCANS.get(best.input).name(), true, aheadM, behindM)
                : new NearestObstacle(reach, 0.0, 0.0, 0.0, -1, "", false, aheadM, behindM)));
    }

    /**
     * A ring's sensors are spaced wider than an object is small: an object between two sensors is seen by
     * both at about the same range. Its bearing is then the mean of the neighbours' points, not the axis
     * of whichever sensor happened to read a centimetre less.
     */
    private void spread(Closest best) {
        RangeScan s = latest[best.input];
        if (!s.hasPoses() || params.spreadM() == 0) {
            return;
        }
        double sx = best.xM;
        double sy = best.yM;
        int n = 1;
        for (int dir = -1; dir <= 1; dir += 2) {
            for (int k = best.sensor + dir; k >= 0 && k < s.size(); k += dir) {
                double r = s.rangeM(k);
                if (!s.valid(k) || r < params.minValidM() || r - best.rangeM > params.spreadM()) {
                    break;
                }
                double[] p = s.pose(k).orElse(PlanarPose.ORIGIN).pointAt(r, 0);
                if (Math.abs(Math.atan2(p[1], p[0]) - best.bearingRad) > Math.PI / 3) {
                    break;
                }
                sx += p[0];
                sy += p[1];
                n++;
            }
        }
        if (n > 1) {
            best.xM = sx / n;
            best.yM = sy / n;
            best.bearingRad = Math.atan2(best.yM, best.xM);
        }
    }

    /** Scan records that could not be read, since start. */
    public long malformed() {
        return malformed;
    }

    /** The closest reading found so far in one search. */
    private static final class Closest {
        double rangeM = Double.POSITIVE_INFINITY;
        double xM;
        double yM;
        double bearingRad;
        int sensor = -1;
        int input;

        void offer(double r, double[] point, double bearing, int sensorIndex, int inputIndex) {
            if (r < rangeM) {
                rangeM = r;
                xM = point[0];
                yM = point[1];
                bearingRad = bearing;
                sensor = sensorIndex;
                input = inputIndex;
            }
        }

        boolean found() {
            return sensor >= 0;
        }
    }

    /** Makes {@code nearest-distance} methods. */
    public static final class Provider extends SimpleMethodProvider<NearestDistanceParams> {
        public Provider() {
            super("nearest-distance", "The nearest obstacle of one or more range scans, and the nearest ahead and behind",
                    NearestDistanceParams.class, PORTS, (layer, p) -> new NearestDistance(p), Layer.PROCESSING);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
