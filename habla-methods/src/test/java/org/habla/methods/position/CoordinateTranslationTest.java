package org.habla.methods.position;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.methods.gaze.HeadPose;
import org.habla.methods.geometry.CameraModel;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

class CoordinateTranslationTest {

    private static final double RADIUS = 0.05;
    private static final CameraModel CAMERA = new CameraModel(0.993, 0.789, 208, 160, 0.2);

    /**
     * The blob a ball of {@link #RADIUS} at robot-frame ({@code x}, {@code y}) on the floor makes in
     * the {@link #CAMERA} on a head at {@code head}: the silhouette cone sampled all round and
     * projected, its bounding box and centre. Null when the ball is not wholly in view.
     */
    private static ObjectNode projectedBlob(double x, double y, HeadPose head, CameraModel cam, boolean roundToPixels) {
        return projectedBlob(x, y, head, cam, roundToPixels, new double[] {0, 0, cam.heightM()});
    }

    /** The same, with the lens at {@code lens} in the robot frame. */
    private static ObjectNode projectedBlob(double x, double y, HeadPose head, CameraModel cam, boolean roundToPixels,
            double[] lens) {
        double[] rel = {x - lens[0], y - lens[1], RADIUS - lens[2]};
        double[] c = BlobFix.toCamera(rel, head);
        double dist = Math.sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        if (c[0] <= 0) {
            return null;
        }
        double alpha = Math.asin(RADIUS / dist);
        double[] u = {c[0] / dist, c[1] / dist, c[2] / dist};
        double[] a = normalize(cross(u, Math.abs(u[2]) < 0.9 ? new double[] {0, 0, 1} : new double[] {0, 1, 0}));
        double[] b = cross(u, a);
        double minX = Double.MAX_VALUE;
        double maxX = -Double.MAX_VALUE;
        double minY = Double.MAX_VALUE;
        double maxY = -Double.MAX_VALUE;
        for (int k = 0; k < 720; k++) {
            double phi = 2 * Math.PI * k / 720;
            double[] d = new double[3];
            for (int i = 0; i < 3; i++) {
                d[i] = Math.cos(alpha) * u[i] + Math.sin(alpha) * (Math.cos(phi) * a[i] + Math.sin(phi) * b[i]);
            }
            double[] p = cam.project(d[0], d[1], d[2]);
            minX = Math.min(minX, p[0]);
            maxX = Math.max(maxX, p[0]);
            minY = Math.min(minY, p[1]);
            maxY = Math.max(maxY, p[1]);
        }
        if (roundToPixels) {
            minX = Math.round(minX);
            minY = Math.round(minY);
            maxX = Math.round(maxX);
            maxY = Math.round(maxY);
        }
        if (minX < 1 || minY < 1 || maxX > cam.width() - 1 || maxY > cam.height() - 1) {
            return null;
        }
        ObjectNode blob = JsonNodeFactory.instance.objectNode();
        double w = maxX - minX;
        double h = maxY - minY;
        blob.put("label", "pink").put("cx", minX + w / 2).put("cy", minY + h / 2)
                .put("area", Math.PI * w * h / 4).put("x", minX).put("y", minY).put("w", w).put("h", h);
        return blob;
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double[] normalize(double[] v) {
        double n = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return new double[] {v[0] / n, v[1] / n, v[2] / n};
    }

    private static RecordValue blobs(CameraModel cam, ObjectNode... list) {
        ObjectNode o = JsonNodeFactory.instance.objectNode().put("width", cam.width()).put("height", cam.height());
        ArrayNode a = o.putArray("blobs");
        for (ObjectNode b : list) {
            a.add(b);
        }
        return RecordValue.of(o);
    }

    private static MethodHarness started(CoordinateTranslationParams p, CameraModel cam) {
        MethodHarness h = MethodHarness.started("where", new CoordinateTranslation(p));
        h.push("camera", cam.toRecord());
        return h;
    }

    /** Worst distance and angle errors over a grid of ball positions and head poses. */
    private static double[] sweep(CameraModel cam, boolean round, int[] count) {
        return sweep(cam, round, count, CoordinateTranslationParams.defaults());
    }

    private static double[] sweep(CameraModel cam, boolean round, int[] count, CoordinateTranslationParams p) {
        MethodHarness h = started(p, cam);
        BlobFix geometry = new BlobFix(cam, RADIUS, p.cameraXM(), p.lensForwardM(), p.minRadiusPx());
        double worstD = 0;
        double worstA = 0;
        HeadPose[] heads = {new HeadPose(0, 0, 0), new HeadPose(-0.3, 0.4, 0), new HeadPose(-0.5, -0.6, 0.1),
            new HeadPose(-0.15, 0.9, 0), new HeadPose(-0.7, 0, 0.2)};
        for (HeadPose head : heads) {
            h.push("head", head.toRecord());
            for (double range = 0.3; range <= 2.0001; range += 0.1) {
                for (double bearing = -1.4; bearing <= 1.4; bearing += 0.1) {
                    double x = range * Math.cos(bearing);
                    double y = range * Math.sin(bearing);
                    ObjectNode blob = projectedBlob(x, y, head, cam, round, geometry.lens(head));
                    if (blob == null) {
                        continue;
                    }
                    h.push("blobs", blobs(cam, blob));
                    RecordValue pos = (RecordValue) h.last("position");
                    assertThat(pos.get("seen").booleanValue()).isTrue();
                    worstD = Math.max(worstD, Math.abs(pos.number("distanceM") - (range - RADIUS - p.bodyRadiusM())));
                    worstA = Math.max(worstA, Math.abs(pos.number("angleRad") - bearing));
                    count[0]++;
                }
            }
        }
        return new double[] {worstD, worstA};
    }

    @Test
    void aBallInTheImageIsPlacedWithin10CmAnd3DegreesFrom30CmTo2M() {
        int[] count = {0};
        double[] worst = sweep(CAMERA, false, count);
        System.out.printf("coordinate-translation: %d positions 0.3-2.0 m, worst distance error %.3f m, angle %.2f deg%n",
                count[0], worst[0], Math.toDegrees(worst[1]));
        assertThat(count[0]).isGreaterThan(60);
        assertThat(worst[0]).isLessThan(0.1);
        assertThat(Math.toDegrees(worst[1])).isLessThan(3);
    }

    @Test
    void wholePixelBlobsOfA416By320ImageKeepTheAngleAndAlmostTheDistance() {
        int[] count = {0};
        double[] worst = sweep(CAMERA.withSize(416, 320), true, count);
        System.out.printf("coordinate-translation: 416x320 whole-pixel boxes, %d positions, worst %.3f m, %.2f deg%n",
                count[0], worst[0], Math.toDegrees(worst[1]));
        assertThat(count[0]).isGreaterThan(60);
        assertThat(worst[0]).as("a ball 2 m away is 19 px wide; half a pixel each side is 5 %").isLessThan(0.1);
        assertThat(Math.toDegrees(worst[1])).isLessThan(3);
    }

    @Test
    void aLensAheadOfThePanAxisAndTheBodysEdgeAreAccountedFor() {
        CoordinateTranslationParams p = ParamsJson.of(CoordinateTranslationParams.class, "{\"cameraXM\": 0.08, \"lensForwardM\": 0.07, \"bodyRadiusM\": 0.15}");
        int[] count = {0};
        double[] worst = sweep(CAMERA, false, count, p);
        System.out.printf("coordinate-translation: lens 0.08 + 0.07 m ahead, body radius 0.15 m, %d positions, worst %.3f m, "
                + "%.2f deg%n", count[0], worst[0], Math.toDegrees(worst[1]));
        assertThat(count[0]).isGreaterThan(60);
        assertThat(worst[0]).isLessThan(0.1);
        assertThat(Math.toDegrees(worst[1])).isLessThan(3);
    }

    @Test
    void aBlobIsPlacedWithTheHeadPoseOfTheMomentItsImageWasTaken() {
        MethodHarness h = started(CoordinateTranslationParams.defaults(), CAMERA);
        long t0 = h.nowMicros();
        HeadPose then = new HeadPose(-0.3, 0.2, 0);
        HeadPose now = new HeadPose(-0.3, 0.5, 0);
        h.push("head", then.toRecord(), t0);
        h.push("head", now.toRecord(), t0 + 100_000);
        ObjectNode blob = projectedBlob(1.0, 0.3, then, CAMERA, false);
        h.push("blobs", blobs(CAMERA, blob), t0 + 60_000);
        RecordValue matched = (RecordValue) h.last("position");
        assertThat(matched.number("angleRad")).isCloseTo(Math.atan2(0.3, 1.0), within(0.01));
        h.push("blobs", blobs(CAMERA, blob), t0 + 120_000);
        RecordValue skewed = (RecordValue) h.last("position");
        assertThat(skewed.number("angleRad") - Math.atan2(0.3, 1.0)).as("the later pose turns it by the pan moved")
                .isCloseTo(0.3, within(0.02));
    }

    @Test
    void noBlobOfTheLabelSaysNotSeenAndKeepsTheLastSighting() {
        MethodHarness h = started(CoordinateTranslationParams.defaults(), CAMERA);
        HeadPose head = new HeadPose(-0.3, 0, 0);
        h.push("head", head.toRecord());
        h.push("blobs", blobs(CAMERA, projectedBlob(1.0, 0.2, head, CAMERA, false)));
        RecordValue seen = (RecordValue) h.last("position");
        ObjectNode green = projectedBlob(0.6, -0.1, head, CAMERA, false).put("label", "green");
        h.push("blobs", blobs(CAMERA, green));
        RecordValue lost = (RecordValue) h.last("position");
        assertThat(lost.get("seen").booleanValue()).isFalse();
        assertThat(lost.number("distanceM")).isEqualTo(seen.number("distanceM"));
        assertThat(lost.number("angleRad")).isCloseTo(Math.atan2(0.2, 1.0), within(0.03));
    }

    @Test
    void aBlobCutByTheBorderIsPlacedByTheGroundPlane() {
        MethodHarness h = started(CoordinateTranslationParams.defaults(), CAMERA);
        HeadPose head = new HeadPose(-0.4, 0, 0);
        h.push("head", head.toRecord());
        ObjectNode blob = projectedBlob(0.8, 0, head, CAMERA, false);
        double keepRight = blob.get("x").doubleValue() + blob.get("w").doubleValue();
        double cy = blob.get("cy").doubleValue();
        double cutH = blob.get("h").doubleValue();
        // The same ball half out of the top and bottom... and the left: only its centre row is right.
        blob.put("x", 0.0).put("w", keepRight).put("y", 0.0).put("h", CAMERA.height()).put("cy", cy);
        assertThat(cutH).isLessThan(CAMERA.height());
        h.push("blobs", blobs(CAMERA, blob));
        RecordValue pos = (RecordValue) h.last("position");
        assertThat(pos.get("method").asText()).isEqualTo("ground");
        assertThat(pos.get("seen").booleanValue()).isTrue();
        assertThat(pos.number("distanceM")).isCloseTo(0.8 - RADIUS, within(0.1));
    }

    @Test
    void aRangeSensorsNearestRecordPassesThroughWithSeenAndTheWorldFrameFromOdometry() {
        MethodHarness h = MethodHarness.started("where", new CoordinateTranslation(CoordinateTranslationParams.defaults()));
        h.push("odometry", RecordValue.builder().put("xM", 1.0).put("yM", 2.0).put("thetaRad", Math.PI / 2).build());
        h.push("nearest", RecordValue.builder().put("distanceM", 0.5).put("angleRad", 0.0).put("xM", 0.5)
                .put("yM", 0.0).put("sensor", 3L).build());
        RecordValue pos = (RecordValue) h.last("position");
        assertThat(pos.get("seen").booleanValue()).isTrue();
        assertThat(pos.number("distanceM")).isEqualTo(0.5);
        assertThat(pos.number("xWorldM")).isCloseTo(1.0, within(1e-9));
        assertThat(pos.number("yWorldM")).isCloseTo(2.5, within(1e-9));
        h.push("nearest", RecordValue.builder().put("distanceM", "far").build());
        RecordValue bad = (RecordValue) h.last("position");
        assertThat(bad.get("seen").booleanValue()).isFalse();
        assertThat(bad.number("xM")).isEqualTo(0.5);
    }

    @Test
    void withoutCameraGeometryABlobIsNotSeenAndNothingFails() {
        MethodHarness h = MethodHarness.started("where", new CoordinateTranslation(CoordinateTranslationParams.defaults()));
        h.push("blobs", blobs(CAMERA, projectedBlob(1.0, 0, HeadPose.STRAIGHT, CAMERA, false)));
        assertThat(((RecordValue) h.last("position")).get("seen").booleanValue()).isFalse();
        h.push("blobs", RecordValue.builder().put("blobs", "garbage").build());
        assertThat(h.state()).isEqualTo(org.habla.method.MethodState.RUNNING);
    }
}
