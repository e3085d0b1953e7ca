package org.habla.methods.gaze;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import org.habla.method.MethodHarness;
import org.habla.methods.geometry.CameraModel;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.Test;

class HeadControlTest {

    private static final CameraModel CAMERA = new CameraModel(0.993, 0.789, 208, 160, 0.2);

    /** The pixel of a point (x forward, y left, z up, relative to the camera) seen with the head at {@code head}. */
    private static double[] pixel(double[] p, HeadPose head) {
        double yaw = -head.panRad();
        double x1 = p[0] * Math.cos(yaw) - p[1] * Math.sin(yaw);
        double y1 = p[0] * Math.sin(yaw) + p[1] * Math.cos(yaw);
        double pitch = -head.pitchRad();
        double x2 = x1 * Math.cos(pitch) - p[2] * Math.sin(pitch);
        double z2 = x1 * Math.sin(pitch) + p[2] * Math.cos(pitch);
        return CAMERA.project(x2, y1, z2);
    }

    private static RecordValue blobsAt(double[] px, String label) {
        ObjectNode o = JsonNodeFactory.instance.objectNode().put("width", 208).put("height", 160);
        ArrayNode a = o.putArray("blobs");
        a.addObject().put("label", label).put("cx", px[0]).put("cy", px[1]).put("area", 30)
                .put("x", px[0] - 3).put("y", px[1] - 3).put("w", 6).put("h", 6);
        return RecordValue.of(o);
    }

    private static RecordValue noBlobs() {
        ObjectNode o = JsonNodeFactory.instance.objectNode().put("width", 208).put("height", 160);
        o.putArray("blobs");
        return RecordValue.of(o);
    }

    private static HeadPose pose(Payload v) {
        return HeadPose.fromVector((VectorValue) v).orElseThrow();
    }

    @Test
    void theHeadTurnsUntilTheTargetSitsInTheMiddleOfTheImage() {
        MethodHarness h = MethodHarness.started("gaze", new HeadControl(HeadControlParams.defaults()));
        h.push("camera", CAMERA.toRecord());
        double[] ball = {0.8, 0.35, -0.15};
        HeadPose head = new HeadPose(-0.1, 0.0, 0);
        h.push("head", head.toRecord());
        double[] first = pixel(ball, head);
        for (int i = 0; i < 12; i++) {
            h.push("blobs", blobsAt(pixel(ball, head), "pink"));
            head = pose(h.last("head"));
            h.push("head", head.toRecord());
            h.advanceMillis(50);
        }
        double[] last = pixel(ball, head);
        System.out.printf("head-control: target from (%.1f, %.1f) px to (%.1f, %.1f) px in 12 images%n",
                first[0], first[1], last[0], last[1]);
        assertThat(Math.abs(first[0] - 104)).isGreaterThan(40);
        assertThat(Math.abs(last[0] - 104)).isLessThan(4);
        assertThat(Math.abs(last[1] - 80)).isLessThan(4);
        assertThat(head.panRad()).isBetween(0.3, 0.6);
    }

    @Test
    void aLostTargetMakesTheHeadSweepWithinTheScanRangeUntilItIsSeenAgain() {
        HeadControl control = new HeadControl(HeadControlParams.defaults());
        MethodHarness h = MethodHarness.started("gaze", control);
        h.push("camera", CAMERA.toRecord());
        h.push("blobs", noBlobs());
        h.advanceMillis(900);
        assertThat(h.values("head")).isEmpty();
        h.advanceMillis(6000);
        List<Payload> sweep = h.values("head");
        assertThat(control.scanning()).isTrue();
        assertThat(sweep.size()).isGreaterThan(50);
        double min = 0;
        double max = 0;
        for (Payload p : sweep) {
            HeadPose hp = pose(p);
            assertThat(hp.tiltRad()).isEqualTo(-0.35);
            assertThat(Math.abs(hp.panRad())).isLessThanOrEqualTo(1.2);
            min = Math.min(min, hp.panRad());
            max = Math.max(max, hp.panRad());
        }
        assertThat(max).as("reaches the left end").isEqualTo(1.2);
        assertThat(min).as("turns back towards the right").isLessThan(0);
        double step = pose(sweep.get(1)).panRad() - pose(sweep.get(0)).panRad();
        assertThat(Math.abs(step)).isCloseTo(0.06, org.assertj.core.api.Assertions.within(1e-9));
        h.clear();
        h.push("blobs", blobsAt(new double[] {150, 60}, "pink"));
        assertThat(control.scanning()).isFalse();
        assertThat(h.values("head")).hasSize(1);
        h.advanceMillis(500);
        assertThat(h.values("head")).as("no scan right after a sighting").hasSize(1);
    }

    @Test
    void theCorrectionStartsFromThePoseTheImageWasTakenAt() {
        MethodHarness h = MethodHarness.started("gaze", new HeadControl(HeadControlParams.defaults()));
        h.push("camera", CAMERA.toRecord());
        long t0 = h.nowMicros();
        h.push("head", new HeadPose(-0.2, 0.1, 0).toRecord(), t0);
        h.push("head", new HeadPose(-0.2, 0.4, 0).toRecord(), t0 + 80_000);
        h.push("blobs", blobsAt(new double[] {104, 80}, "pink"), t0 + 40_000);
        assertThat(pose(h.last("head")).panRad()).as("centred in an image taken at pan 0.1").isEqualTo(0.1);
    }

    @Test
    void blobsOfOtherLabelsAreIgnoredAndCommandsStayWithinTheLimits() {
        MethodHarness h = MethodHarness.started("gaze", new HeadControl(HeadControlParams.defaults()));
        h.push("camera", CAMERA.toRecord());
        h.push("head", new HeadPose(-1.3, 1.6, 0).toRecord());
        h.push("blobs", blobsAt(new double[] {10, 150}, "green"));
        assertThat(h.values("head")).isEmpty();
        h.push("blobs", blobsAt(new double[] {0, 159}, "pink"));
        HeadPose p = pose(h.last("head"));
        assertThat(p.panRad()).isEqualTo(1.62);
        assertThat(p.tiltRad()).isEqualTo(-1.31);
    }
}
