package org.habla.methods.sensors;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.MethodHarness;
import org.habla.methods.gaze.HeadPose;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class HeadTest {

    private static double[] last(MethodHarness h) {
        return ((VectorValue) h.last("head")).toArray();
    }

    @Test
    void commandsAreClampedToTheDefaultJointLimits() {
        MethodHarness h = MethodHarness.started("head", new Head(HeadParams.defaults()));
        h.push("command", VectorValue.of(-0.5, 0.3, 0.2));
        assertThat(h.last("head")).isEqualTo(VectorValue.of(-0.5, 0.3, 0.2));
        h.push("command", VectorValue.of(-2.0, 3.0, 1.5));
        assertThat(h.last("head")).isEqualTo(VectorValue.of(-1.31, 1.62, 0.79));
        h.push("command", VectorValue.of(0.5, -3.0));
        assertThat(h.last("head")).isEqualTo(VectorValue.of(0.05, -1.62, 0));
    }

    @Test
    void limitsComeFromThePoseChannelsMetadataUnlessParamsSayOtherwise() {
        ObjectNode meta = JsonNodeFactory.instance.objectNode().put("tiltMinRad", -1.0).put("tiltMaxRad", 0.0)
                .put("panMinRad", -0.5).put("panMaxRad", 0.5).put("nodMinRad", -0.1).put("nodMaxRad", 0.1);
        ChannelDescriptor channel = ChannelDescriptor.reading("head-pose", PayloadKind.RECORD, "rad").withMetadata(meta);
        HeadParams p = new HeadParams(null, null, null, 0.8, null, null);
        MethodHarness h = MethodHarness.of("head", new Head(p)).wireChannel("pose", channel).start();
        h.push("command", VectorValue.of(-3, 3, 3));
        double[] c = last(h);
        assertThat(c[0]).isEqualTo(-1.0);
        assertThat(c[1]).isEqualTo(0.8);
        assertThat(c[2]).isEqualTo(0.1);
    }

    @Test
    void poseReadingsAreHandedOnAndMalformedOnesDropped() {
        Head head = new Head(HeadParams.defaults());
        MethodHarness h = MethodHarness.started("head", head);
        h.push("pose", RecordValue.builder().put("tiltRad", -0.2).put("panRad", 0.4).put("nodRad", 0.1).build());
        h.push("pose", RecordValue.builder().put("tiltRad", "down").put("panRad", 0.4).build());
        h.push("command", VectorValue.of(Double.NaN, 0, 0));
        assertThat(h.values("pose")).hasSize(1);
        assertThat(((RecordValue) h.last("pose")).number("panRad")).isCloseTo(0.4, within(1e-12));
        assertThat(h.values("head")).isEmpty();
        assertThat(head.rejected()).isEqualTo(2);
    }

    /** A head pose typed by a driver, which this module does not know: read field by field, as JSON would be. */
    record DriverHeadPose(double tiltRad, double panRad, double nodRad) implements RecordForm {
        static final RecordLayout<DriverHeadPose> LAYOUT = RecordLayout.of(DriverHeadPose.class)
                .number("tiltRad", DriverHeadPose::tiltRad).doc("tilt")
                .number("panRad", DriverHeadPose::panRad).doc("pan")
                .number("nodRad", DriverHeadPose::nodRad).doc("nod")
                .build();

        @Override
        public RecordLayout<DriverHeadPose> layout() {
            return LAYOUT;
        }
    }

    @Test
    void aPoseReadingTypedByTheDriverIsHandedOnAsAHeadPose() {
        MethodHarness h = MethodHarness.started("head", new Head(HeadParams.defaults()));
        h.push("pose", RecordValue.of(new DriverHeadPose(-0.5, 0.25, 0.125)));
        RecordValue pose = (RecordValue) h.last("pose");
        assertThat(pose.form(HeadPose.class)).contains(new HeadPose(-0.5, 0.25, 0.125));
    }
}
