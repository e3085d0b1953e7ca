package org.habla.methods.sensors;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
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
import org.habla.methods.geometry.PlanarPose;
import org.habla.methods.geometry.RangeScan;
import org.habla.plugin.SimpleMethodProvider;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.VectorValue;

/**
 * A general range sensor method, types {@code sonar}, {@code infrared} and {@code laser}: it stores the ranges of a
 * ring of sensors (input {@code ranges}, a VECTOR in metres from any driver), cleans them and hands
 * them on as {@code ranges} and as a {@code scan} record that carries each sensor's pose. A reading
 * that is not a finite number, is negative, or reaches the sensor's range means "nothing seen": it
 * becomes the sensor's maximum range and is marked not valid. Geometry comes from params or from the
 * channel's metadata, never from knowing the robot — an ARCOS sonar ring and a sonar behind HABLA's
 * own interface protocol are handled the same way.
 *
 * <p>Sensors whose metadata pose says {@code "mount": "head"} turn with the head's pan when the
 * optional input {@code head} (a RECORD with {@code panRad}) is wired.
 */
public final class RangeSensor extends SensorActuatorMethod {

    private static final OutputPort<VectorValue> RANGES_OUT = OutputPort.of("ranges", VectorValue.class,
            Shape.vector("m", "cleaned range per sensor; the maximum range where nothing was seen"));
    private static final OutputPort<RecordValue> SCAN = OutputPort.of("scan", RecordValue.class,
            Shape.record("ranges with validity, reach and pose per sensor", RangeScan.LAYOUT));
    private static final InputPort<VectorValue> RANGES_IN = InputPort.of("ranges", VectorValue.class);
    private static final InputPort<RecordValue> HEAD = InputPort.optional("head", RecordValue.class, Delivery.latest());
    static final Ports PORTS = Ports.of(RANGES_OUT, SCAN, RANGES_IN, HEAD);

    /** A laser's reach when neither params nor the channel's metadata give one. */
    static final double LASER_REACH_M = 10.0;

    private final RangeSensorParams params;
    private final double fallbackMaxRangeM;
    private final Output<VectorValue> rangesOut = output(RANGES_OUT);
    private final Output<RecordValue> scanOut = output(SCAN);
    private final Input<VectorValue> ranges = input(RANGES_IN, this::onRanges);
    private final Input<RecordValue> head = input(HEAD, this::onHead);

    private List<PlanarPose> poses = List.of();
    private boolean[] onHead = new boolean[0];
    private double[] minRangesM = new double[0];
    private double[] maxRangesM = new double[0];
    private double defaultMaxM;
    private double defaultMinM;
    private double headPanRad;
    private long invalidReadings;
    private long geometryMismatches;

    RangeSensor(RangeSensorParams params, double fallbackMaxRangeM) {
        this.params = params;
        this.fallbackMaxRangeM = fallbackMaxRangeM;
    }

    @Override
    protected void onStart() {
        ObjectNode meta = channelOf(ranges).map(ChannelDescriptor::metadata).orElse(null);
        defaultMaxM = params.maxRangeM() != null ? params.maxRangeM()
                : positiveOr(meta == null ? null : meta.path("maxRangeM"), fallbackMaxRangeM);
        defaultMinM = params.minRangeM() != null ? params.minRangeM()
                : Math.min(positiveOr(meta == null ? null : meta.path("minRangeM"), 0), defaultMaxM / 2);
        List<PlanarPose> found = new ArrayList<>();
        List<Boolean> headMounted = new ArrayList<>();
        List<Double> mins = new ArrayList<>();
        List<Double> maxes = new ArrayList<>();
        if (params.poses() != null) {
            for (PlanarPose p : params.poses()) {
                found.add(p);
                headMounted.add(false);
                mins.add(defaultMinM);
                maxes.add(defaultMaxM);
            }
        } else if (meta != null && meta.path("poses").isArray()) {
            for (JsonNode node : meta.path("poses")) {
                PlanarPose p = PlanarPose.fromJson(node).orElse(null);
                if (p == null) {
                    log().warn("{}: channel metadata has a pose without finite xM, yM, thetaRad; geometry ignored", id());
                    found.clear();
                    break;
                }
                found.add(p);
                headMounted.add("head".equals(node.path("mount").asText()));
                boolean own = params.maxRangeM() == null;
                maxes.add(own ? positiveOr(node.path("maxRangeM"), defaultMaxM) : defaultMaxM);
                mins.add(params.minRangeM() == null ? positiveOr(node.path("minRangeM"), defaultMinM) : defaultMinM);
            }
        }
        poses = List.copyOf(found);
        onHead = new boolean[poses.size()];
        minRangesM = new double[poses.size()];
        maxRangesM = new double[poses.size()];
        for (int i = 0; i < poses.size(); i++) {
            onHead[i] = headMounted.get(i);
            maxRangesM[i] = maxes.get(i);
            minRangesM[i] = Math.min(mins.get(i), maxRangesM[i] / 2);
        }
    }

    private void onHead(RecordValue value, Sample sample) {
        JsonNode pan = value.get("panRad");
        if (pan.isNumber() && Double.isFinite(pan.doubleValue())) {
            headPanRad = pan.doubleValue();
        }
    }

    private void onRanges(VectorValue value, Sample sample) {
        int n = value.size();
        if (n == 0 || n > RangeScan.MAX_SENSORS) {
            invalidReadings++;
            log().warn("{}: a range vector of {} values was ignored (1..{} allowed)", id(), n, RangeScan.MAX_SENSORS);
            return;
        }
        boolean geometry = poses.size() == n;
        if (!geometry && !poses.isEmpty() && geometryMismatches++ == 0) {
            log().warn("{}: {} ranges but {} sensor poses; the scan carries no poses", id(), n, poses.size());
        }
        double[] cleaned = new double[n];
        boolean[] valid = new boolean[n];
        double[] reach = new double[n];
        List<PlanarPose> turned = new ArrayList<>(geometry ? n : 0);
        for (int i = 0; i < n; i++) {
            double max = geometry ? maxRangesM[i] : defaultMaxM;
            double min = geometry ? minRangesM[i] : defaultMinM;
            double r = value.get(i);
            reach[i] = max;
            if (!Double.isFinite(r) || r < 0) {
                invalidReadings++;
                cleaned[i] = max;
            } else if (r >= max) {
                cleaned[i] = max;
            } else {
                cleaned[i] = Math.max(r, min);
                valid[i] = true;
            }
            if (geometry) {
                boolean pan = onHead[i] && params.panWithHead();
                turned.add(pan ? poses.get(i).turnedAboutOrigin(headPanRad) : poses.get(i));
            }
        }
        emit(rangesOut, VectorValue.wrap(cleaned.clone()));
        emit(scanOut, new RangeScan(cleaned, valid, reach, turned).toRecord());
    }

    /** Readings that were not finite, non-negative numbers (or vectors of a wrong size), since start. */
    public long invalidReadings() {
        return invalidReadings;
    }

    private static double positiveOr(JsonNode node, double fallback) {
        return node != null && node.isNumber() && node.doubleValue() >= 0 && Double.isFinite(node.doubleValue())
                ? node.doubleValue() : fallback;
    }

    /** Makes {@code sonar} methods. */
    public static final class SonarProvider extends SimpleMethodProvider<RangeSensorParams> {
        public SonarProvider() {
            super("sonar", "Cleans sonar ranges (nothing seen = maximum range) and adds each transducer's pose",
                    RangeSensorParams.class, PORTS, (layer, p) -> new RangeSensor(p, 5.0), Layer.SENSORS_ACTUATORS);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }

    /**
     * Makes {@code laser} methods: a laser scanner's beams, gathered into the sectors of a ring of virtual sensors
     * on the body's edge (as {@code habla-ros2 body} sends them), each with its pose in the channel's metadata.
     */
    public static final class LaserProvider extends SimpleMethodProvider<RangeSensorParams> {
        public LaserProvider() {
            super("laser", "Cleans the ranges of a laser scanner's sectors (nothing seen = maximum range) and adds each sector's pose",
                    RangeSensorParams.class, PORTS, (layer, p) -> new RangeSensor(p, LASER_REACH_M), Layer.SENSORS_ACTUATORS);
        }
    }

    /** Makes {@code infrared} methods. */
    public static final class InfraredProvider extends SimpleMethodProvider<RangeSensorParams> {
        public InfraredProvider() {
            super("infrared", "Cleans infrared ranges (nothing seen = maximum range) and adds each sensor's pose",
                    RangeSensorParams.class, PORTS, (layer, p) -> new RangeSensor(p, 1.5), Layer.SENSORS_ACTUATORS);
        }

        /** Microseconds per sample, no ticks, nothing that blocks: may run on the thread that delivers to it. */
        @Override
        public boolean light() {
            return true;
        }
    }
}
