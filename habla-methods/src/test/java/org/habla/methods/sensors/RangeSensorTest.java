package org.habla.methods.sensors;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.MethodHarness;
import org.habla.methods.geometry.PlanarPose;
import org.habla.methods.geometry.RangeScan;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class RangeSensorTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    private static ChannelDescriptor sonarChannel(String metadata) throws Exception {
        return ChannelDescriptor.reading("sonar", PayloadKind.VECTOR, "m")
                .withMetadata((ObjectNode) JSON.readTree(metadata));
    }

    @Test
    void nothingSeenAndGarbageBecomeTheMaximumRangeAndAreNotValid() throws Exception {
        RangeSensor m = new RangeSensor(RangeSensorParams.defaults(), 5.0);
        MethodHarness h = MethodHarness.of("sonar", m)
                .wireChannel("ranges", sonarChannel("{\"maxRangeM\": 4.0, \"minRangeM\": 0.1}")).start();
        h.push("ranges", VectorValue.of(1.5, 4.0, 9.0, Double.NaN, -1, 0.02, Double.POSITIVE_INFINITY));
        assertThat(h.last("ranges")).isEqualTo(VectorValue.of(1.5, 4.0, 4.0, 4.0, 4.0, 0.1, 4.0));
        RangeScan scan = RangeScan.fromRecord((RecordValue) h.last("scan"));
        assertThat(scan.valid(0)).isTrue();
        assertThat(scan.valid(1)).isFalse();
        assertThat(scan.valid(5)).isTrue();
        assertThat(scan.hasPoses()).isFalse();
        assertThat(m.invalidReadings()).isEqualTo(3);
    }

    @Test
    void theScanCarriesThePosesFromTheChannelMetadata() throws Exception {
        String meta = "{\"maxRangeM\": 5.0, \"poses\": [{\"xM\":0.1,\"yM\":0.2,\"thetaRad\":1.5708},"
                + "{\"xM\":0.2,\"yM\":0.0,\"thetaRad\":0}]}";
        MethodHarness h = MethodHarness.of("sonar", new RangeSensor(RangeSensorParams.defaults(), 5.0))
                .wireChannel("ranges", sonarChannel(meta)).start();
        h.push("ranges", VectorValue.of(2.0, 3.0));
        RangeScan scan = RangeScan.fromRecord((RecordValue) h.last("scan"));
        assertThat(scan.pose(0)).contains(new PlanarPose(0.1, 0.2, 1.5708));
        assertThat(scan.pose(1)).contains(new PlanarPose(0.2, 0.0, 0));
        assertThat(scan.rangeM(1)).isEqualTo(3.0);
    }

    @Test
    void paramsOverrideTheMetadataAndAMismatchedRingLosesOnlyItsPoses() throws Exception {
        RangeSensorParams p = new RangeSensorParams(2.0, null, List.of(new PlanarPose(0, 0, 0)), true);
        MethodHarness h = MethodHarness.of("ir", new RangeSensor(p, 1.5))
                .wireChannel("ranges", sonarChannel("{\"maxRangeM\": 9.0}")).start();
        h.push("ranges", VectorValue.of(2.5));
        assertThat(h.last("ranges")).isEqualTo(VectorValue.of(2.0));
        h.push("ranges", VectorValue.of(1.0, 1.0));
        RangeScan scan = RangeScan.fromRecord((RecordValue) h.last("scan"));
        assertThat(scan.size()).isEqualTo(2);
        assertThat(scan.hasPoses()).isFalse();
    }

    @Test
    void headMountedSensorsTurnWithTheHeadsPan() throws Exception {
        String meta = "{\"poses\": [{\"xM\":0.2,\"yM\":0,\"thetaRad\":0,\"mount\":\"head\",\"maxRangeM\":0.5},"
                + "{\"xM\":0.1,\"yM\":0,\"thetaRad\":0,\"mount\":\"body\",\"maxRangeM\":0.9}]}";
        MethodHarness h = MethodHarness.of("ir", new RangeSensor(RangeSensorParams.defaults(), 1.5))
                .wireChannel("ranges", sonarChannel(meta)).start();
        h.push("head", RecordValue.builder().put("panRad", Math.PI / 2).put("tiltRad", 0.0).build());
        h.push("ranges", VectorValue.of(0.7, 0.7));
        RangeScan scan = RangeScan.fromRecord((RecordValue) h.last("scan"));
        assertThat(scan.valid(0)).as("beyond the head sensor's own 0.5 m reach").isFalse();
        assertThat(scan.valid(1)).isTrue();
        PlanarPose turned = scan.pose(0).orElseThrow();
        assertThat(turned.xM()).isCloseTo(0, within(1e-9));
        assertThat(turned.yM()).isCloseTo(0.2, within(1e-9));
        assertThat(turned.thetaRad()).isCloseTo(Math.PI / 2, within(1e-9));
        assertThat(scan.pose(1)).contains(new PlanarPose(0.1, 0, 0));
    }
}
