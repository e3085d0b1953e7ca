package org.habla.methods.perception;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.methods.geometry.PlanarPose;
import org.habla.methods.geometry.RangeScan;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

class NearestDistanceTest {

    /** Four sensors: left, front, right, rear, each 0.2 m from the centre facing outwards. */
    private static final List<PlanarPose> RING = List.of(new PlanarPose(0, 0.2, Math.PI / 2),
            new PlanarPose(0.2, 0, 0), new PlanarPose(0, -0.2, -Math.PI / 2), new PlanarPose(-0.2, 0, Math.PI));

    private static RecordValue scan(double... ranges) {
        boolean[] valid = new boolean[ranges.length];
        double[] reach = new double[ranges.length];
        for (int i = 0; i < ranges.length; i++) {
            valid[i] = ranges[i] < 5.0;
            reach[i] = 5.0;
        }
        return new RangeScan(ranges, valid, reach, RING).toRecord();
    }

    @Test
    void theNearestValidReadingIsPlacedInTheRobotFrame() {
        MethodHarness h = MethodHarness.started("nearest", new NearestDistance(NearestDistanceParams.defaults()));
        h.push("scan", scan(0.5, 1.0, 5.0, 2.0));
        RecordValue n = (RecordValue) h.last("nearest");
        assertThat(n.number("distanceM")).isEqualTo(0.5);
        assertThat(n.number("xM")).isCloseTo(0, within(1e-9));
        assertThat(n.number("yM")).isCloseTo(0.7, within(1e-9));
        assertThat(n.number("angleRad")).isCloseTo(Math.PI / 2, within(1e-9));
        assertThat(n.number("sensor")).isEqualTo(0);
        assertThat(n.get("valid").booleanValue()).isTrue();
        assertThat(n.number("aheadM")).isEqualTo(1.0);
        assertThat(n.number("behindM")).isEqualTo(2.0);
    }

    @Test
    void anObjectSeenByTwoNeighbouringSensorsLiesBetweenThem() {
        // Two front sensors at +10° and -10°: a small object straight ahead reads about the same on both.
        List<PlanarPose> pair = List.of(new PlanarPose(0.2, 0.03, Math.toRadians(10)),
                new PlanarPose(0.2, -0.03, Math.toRadians(-10)));
        MethodHarness h = MethodHarness.started("nearest", new NearestDistance(NearestDistanceParams.defaults()));
        h.push("scan", new RangeScan(new double[] {1.02, 1.0}, new boolean[] {true, true}, new double[] {5, 5}, pair)
                .toRecord());
        RecordValue n = (RecordValue) h.last("nearest");
        assertThat(n.number("distanceM")).isEqualTo(1.0);
        assertThat(n.number("angleRad")).isCloseTo(0, within(Math.toRadians(1)));
        // Far apart in range, they see different things: the nearer one's axis stands.
        h.push("scan", new RangeScan(new double[] {1.5, 1.0}, new boolean[] {true, true}, new double[] {5, 5}, pair)
                .toRecord());
        assertThat(((RecordValue) h.last("nearest")).number("angleRad")).isLessThan(Math.toRadians(-8));
    }

    @Test
    void readingsBelowMinValidAndNothingSeenAreIgnored() {
        MethodHarness h = MethodHarness.started("nearest",
                new NearestDistance(ParamsJson.of(NearestDistanceParams.class, "{\"minValidM\": 0.1}")));
        h.push("scan", scan(0.05, 5.0, 5.0, 5.0));
        RecordValue n = (RecordValue) h.last("nearest");
        assertThat(n.get("valid").booleanValue()).isFalse();
        assertThat(n.number("sensor")).isEqualTo(-1);
        assertThat(n.number("distanceM")).isEqualTo(5.0);
        assertThat(n.number("aheadM")).isEqualTo(5.0);
    }

    @Test
    void twoScansAreCombinedAndAStaleOneIsLeftOut() {
        MethodHarness h = MethodHarness.started("nearest", new NearestDistance(NearestDistanceParams.defaults()));
        RecordValue ir = new RangeScan(new double[] {0.3}, new boolean[] {true}, new double[] {1.0},
                List.of(new PlanarPose(0.1, 0, 0))).toRecord();
        h.push("scan2", ir);
        h.push("scan", scan(4.0, 1.0, 4.0, 4.0));
        RecordValue n = (RecordValue) h.last("nearest");
        assertThat(n.number("distanceM")).isEqualTo(0.3);
        assertThat(n.text("input")).isEqualTo("scan2");
        assertThat(n.number("aheadM")).isEqualTo(0.3);
        h.advanceMillis(1500).push("scan", scan(4.0, 1.0, 4.0, 4.0));
        assertThat(((RecordValue) h.last("nearest")).number("distanceM")).as("the old infrared scan is left out")
                .isEqualTo(1.0);
    }

    @Test
    void aMalformedScanIsCountedAndTheMethodGoesOn() {
        NearestDistance m = new NearestDistance(NearestDistanceParams.defaults());
        MethodHarness h = MethodHarness.started("nearest", m);
        h.push("scan", RecordValue.builder().put("rangesM", "lots").build());
        assertThat(h.values("nearest")).isEmpty();
        h.push("scan", scan(5.0, 0.9, 5.0, 5.0));
        assertThat(((RecordValue) h.last("nearest")).number("angleRad")).isCloseTo(0, within(1e-9));
        assertThat(m.malformed()).isEqualTo(1);
    }
}
