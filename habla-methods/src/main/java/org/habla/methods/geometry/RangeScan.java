package org.habla.methods.geometry;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;

/**
 * One reading of a ring of range sensors (sonar, infrared) with the geometry needed to use it: each
 * sensor's range, whether it saw something within its reach, its reach, and, when known, its pose in
 * the robot frame. It travels between methods as the {@code scan} record:
 *
 * <pre>{@code
 * {"rangesM": [0.8, 5.0, ...], "valid": [true, false, ...], "maxRangesM": [5.0, 5.0, ...],
 *  "poses": [{"xM": 0.069, "yM": 0.136, "thetaRad": 1.5708}, ...]}      // "poses" absent when unknown
 * }</pre>
 */
public final class RangeScan implements RecordForm {

    /** The most sensors a scan may hold. */
    public static final int MAX_SENSORS = 256;

    /** The fields of a scan record. */
    public static final RecordLayout<RangeScan> LAYOUT = RecordLayout.of(RangeScan.class)
            .numbers("rangesM", s -> s.rangesM).unit("m").frame("from each sensor, in index order")
            .doc("each sensor's range; its reach when it saw nothing")
            .flags("valid", s -> s.valid).doc("whether each sensor saw something within its reach")
            .numbers("maxRangesM", s -> s.maxRangesM).unit("m").frame("from each sensor").doc("each sensor's reach")
            .array("poses", s -> s.poses.isEmpty() ? null : s.posesJson()).optional().unit("m, rad")
            .frame("robot frame: x forward, y to the left").doc("each sensor's pose {xM, yM, thetaRad}, when known")
            .build();

    private final double[] rangesM;
    private final boolean[] valid;
    private final double[] maxRangesM;
    private final List<PlanarPose> poses;

    /**
     * @param poses one pose per sensor, or an empty list when the geometry is unknown
     */
    public RangeScan(double[] rangesM, boolean[] valid, double[] maxRangesM, List<PlanarPose> poses) {
        int n = rangesM.length;
        if (n == 0 || n > MAX_SENSORS) {
            throw new IllegalArgumentException("a scan holds 1.." + MAX_SENSORS + " ranges, had " + n);
        }
        if (valid.length != n || maxRangesM.length != n || (!poses.isEmpty() && poses.size() != n)) {
            throw new IllegalArgumentException("a scan of " + n + " ranges needs as many flags, reaches and poses");
        }
        for (int i = 0; i < n; i++) {
            if (!Double.isFinite(rangesM[i]) || rangesM[i] < 0 || !(maxRangesM[i] > 0) || !Double.isFinite(maxRangesM[i])) {
                throw new IllegalArgumentException("scan sensor " + i + ": range " + rangesM[i] + " and reach "
                        + maxRangesM[i] + " must be finite and not negative");
            }
        }
        this.rangesM = rangesM.clone();
        this.valid = valid.clone();
        this.maxRangesM = maxRangesM.clone();
        this.poses = List.copyOf(poses);
    }

    public int size() {
        return rangesM.length;
    }

    public double rangeM(int i) {
        return rangesM[i];
    }

    /** Whether sensor {@code i} saw something within its reach. */
    public boolean valid(int i) {
        return valid[i];
    }

    public double maxRangeM(int i) {
        return maxRangesM[i];
    }

    public boolean hasPoses() {
        return !poses.isEmpty();
    }

    /** The pose of sensor {@code i} in the robot frame, if the geometry is known. */
    public Optional<PlanarPose> pose(int i) {
        return poses.isEmpty() ? Optional.empty() : Optional.of(poses.get(i));
    }

    public double[] rangesM() {
        return rangesM.clone();
    }

    /** The {@code scan} record, carrying this scan itself. */
    public RecordValue toRecord() {
        return RecordValue.of(this);
    }

    @Override
    public RecordLayout<RangeScan> layout() {
        return LAYOUT;
    }

    private ArrayNode posesJson() {
        ArrayNode a = JsonNodeFactory.instance.arrayNode(poses.size());
        poses.forEach(pose -> a.add(pose.toJson()));
        return a;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof RangeScan s && Arrays.equals(rangesM, s.rangesM) && Arrays.equals(valid, s.valid)
                && Arrays.equals(maxRangesM, s.maxRangesM) && poses.equals(s.poses);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(rangesM) * 31 + poses.hashCode();
    }

    /** Reads a {@code scan} record; throws {@link IllegalArgumentException} saying what is wrong with it. */
    public static RangeScan fromRecord(RecordValue record) {
        return record.as(RangeScan.class, RangeScan::read);
    }

    private static RangeScan read(RecordValue record) {
        JsonNode r = record.get("rangesM");
        JsonNode v = record.get("valid");
        JsonNode m = record.get("maxRangesM");
        if (!r.isArray() || !v.isArray() || !m.isArray()) {
            throw new IllegalArgumentException("a scan record needs the arrays rangesM, valid and maxRangesM");
        }
        int n = r.size();
        if (n == 0 || n > MAX_SENSORS || v.size() != n || m.size() != n) {
            throw new IllegalArgumentException("a scan record needs 1.." + MAX_SENSORS + " ranges with as many flags and reaches");
        }
        double[] ranges = new double[n];
        boolean[] flags = new boolean[n];
        double[] reaches = new double[n];
        for (int i = 0; i < n; i++) {
            if (!r.get(i).isNumber() || !v.get(i).isBoolean() || !m.get(i).isNumber()) {
                throw new IllegalArgumentException("scan record entry " + i + " is not a number, flag and reach");
            }
            ranges[i] = r.get(i).doubleValue();
            flags[i] = v.get(i).booleanValue();
            reaches[i] = m.get(i).doubleValue();
        }
        List<PlanarPose> poses = new ArrayList<>();
        JsonNode p = record.get("poses");
        if (p.isArray()) {
            if (p.size() != n) {
                throw new IllegalArgumentException("a scan record of " + n + " ranges has " + p.size() + " poses");
            }
            for (JsonNode node : p) {
                poses.add(PlanarPose.fromJson(node).orElseThrow(
                        () -> new IllegalArgumentException("a scan pose needs finite xM, yM and thetaRad: " + node)));
            }
        }
        return new RangeScan(ranges, flags, reaches, poses);
    }
}
