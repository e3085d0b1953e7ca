package org.habla.methods.vision;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.awt.geom.Point2D;
import java.util.Map;
import java.util.Random;
import org.habla.config.ParamsJson;
import org.habla.method.Layer;
import org.habla.method.MethodHarness;
import org.habla.method.MethodState;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.ImageFrame;
import org.habla.sample.Payload;
import org.habla.sample.RecordValue;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

class ImageSegmentationTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    private static MethodHarness started(ImageSegmentationParams params) {
        return MethodHarness.started("seg", new ImageSegmentation(params)).runBackgroundAtOnce();
    }

    /** A bgr8 frame of one colour with a filled rectangle of another. */
    private static ImageFrame bgrWithRectangle(int w, int h, int[] backBgr, int[] rectBgr, int rx, int ry, int rw, int rh) {
        byte[] data = new byte[w * h * 3];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int[] c = x >= rx && x < rx + rw && y >= ry && y < ry + rh ? rectBgr : backBgr;
                int at = (y * w + x) * 3;
                data[at] = (byte) c[0];
                data[at + 1] = (byte) c[1];
                data[at + 2] = (byte) c[2];
            }
        }
        return ImageFrame.wrap(w, h, "bgr8", data);
    }

    private static JsonNode blobList(Payload p) {
        return ((RecordValue) p).get("blobs");
    }

    @ParameterizedTest(name = "{0}x{1}")
    @CsvSource({"208, 160", "416, 320"})
    void ballCentroidIsWithinThreePixelsOfItsProjectedCentre(int width, int height) {
        CameraScene scene = new CameraScene(width, height, 0.2);
        MethodHarness h = started(ImageSegmentationParams.defaults());
        Random random = new Random(width);
        double worst = 0;
        String worstAt = "";
        int positions = 40;
        for (int i = 0; i < positions; i++) {
            double x = 0.6 + random.nextDouble() * 2.0;
            double y = (random.nextDouble() * 2 - 1) * scene.maxLateralM(x);
            h.push("image", scene.render(random, true, x, y));
            RecordValue largest = (RecordValue) h.last("largest");
            assertThat(largest.get("seen").asBoolean()).as("ball seen at x=%.2f y=%.2f", x, y).isTrue();
            assertThat(largest.text("label")).isEqualTo("pink");
            Point2D.Double expected = scene.projectedBallCentre(x, y);
            double error = Math.hypot(largest.number("cx") - expected.x, largest.number("cy") - expected.y);
            if (error > worst) {
                worst = error;
                worstAt = String.format("x=%.2f m y=%.2f m (radius %.1f px)", x, y, scene.ballRadiusPx(x));
            }
            JsonNode blobs = blobList(h.last("blobs"));
            assertThat(blobs.size()).as("one pink blob at x=%.2f y=%.2f", x, y).isEqualTo(1);
            double disc = Math.PI * Math.pow(scene.ballRadiusPx(x), 2);
            assertThat(blobs.get(0).get("area").asDouble()).as("area at x=%.2f", x)
                    .isBetween(0.3 * disc, 1.6 * disc);
        }
        System.out.printf("image-segmentation %dx%d: worst centroid error %.2f px over %d positions, at %s%n",
                width, height, worst, positions, worstAt);
        assertThat(worst).isLessThanOrEqualTo(3.0);
        assertThat(h.values("blobs")).hasSize(positions);
    }

    @ParameterizedTest(name = "{0}x{1}")
    @CsvSource({"208, 160", "416, 320"})
    void framesWithoutTheBallShowNoPinkBlob(int width, int height) {
        CameraScene scene = new CameraScene(width, height, 0.2);
        MethodHarness h = started(ImageSegmentationParams.defaults());
        Random random = new Random(7 + width);
        for (int i = 0; i < 40; i++) {
            h.push("image", scene.render(random, false, 0, 0));
            assertThat(blobList(h.last("blobs"))).as("frame %d", i).isEmpty();
            assertThat(((RecordValue) h.last("largest")).get("seen").asBoolean()).isFalse();
        }
        assertThat(h.values("blobs")).hasSize(40);
    }

    /** Segmentation of {@code colors} without opening or closing. */
    private static ImageSegmentationParams segmenting(Map<String, ColorRange> colors) {
        ImageSegmentationParams p = ParamsJson.of(ImageSegmentationParams.class, "{\"openPx\": 0, \"closePx\": 0}");
        return new ImageSegmentationParams(colors, p.minAreaPx(), 0, 0, p.maxBlobs());
    }

    @Test
    void rectangleIsReportedWithItsExactCentroidAreaAndBox() {
        MethodHarness h = started(ParamsJson.of(ImageSegmentationParams.class, "{\"openPx\": 0, \"closePx\": 0}"));
        h.push("image", bgrWithRectangle(64, 48, new int[] {200, 200, 200}, new int[] {180, 105, 255}, 10, 5, 21, 9));
        JsonNode b = blobList(h.last("blobs")).get(0);
        assertThat(b.get("label").asText()).isEqualTo("pink");
        assertThat(b.get("cx").asDouble()).isEqualTo(20.0);
        assertThat(b.get("cy").asDouble()).isEqualTo(9.0);
        assertThat(b.get("area").asInt()).isEqualTo(21 * 9);
        assertThat(new int[] {b.get("x").asInt(), b.get("y").asInt(), b.get("w").asInt(), b.get("h").asInt()})
                .containsExactly(10, 5, 21, 9);
        RecordValue blobs = (RecordValue) h.last("blobs");
        assertThat(blobs.number("width")).isEqualTo(64);
        assertThat(blobs.number("height")).isEqualTo(48);
    }

    @Test
    void closingDoesNotGlueARegionNearTheEdgeToTheEdge() {
        MethodHarness h = started(ParamsJson.of(ImageSegmentationParams.class, "{\"openPx\": 0, \"closePx\": 5}"));
        h.push("image", bgrWithRectangle(64, 48, new int[] {0, 0, 0}, new int[] {180, 105, 255}, 1, 1, 12, 12));
        JsonNode b = blobList(h.last("blobs")).get(0);
        assertThat(new int[] {b.get("x").asInt(), b.get("y").asInt(), b.get("w").asInt(), b.get("h").asInt(),
                b.get("area").asInt()}).containsExactly(1, 1, 12, 12, 144);
        h.push("image", bgrWithRectangle(64, 48, new int[] {0, 0, 0}, new int[] {180, 105, 255}, 0, 40, 10, 8));
        b = blobList(h.last("blobs")).get(0);
        assertThat(new int[] {b.get("x").asInt(), b.get("y").asInt(), b.get("w").asInt(), b.get("h").asInt(),
                b.get("area").asInt()}).as("a region cut by the edges keeps its pixels").containsExactly(0, 40, 10, 8, 80);
    }

    @Test
    void hueRangeThatWrapsAroundRedTakesBothEndsOfTheHueCircle() {
        int[] red = {20, 10, 230};        // hue 2 (OpenCV scale)
        int[] crimson = {60, 0, 220};      // hue 172
        ColorRange wrapping = ParamsJson.of(ColorRange.class, "{\"hMin\": 170, \"hMax\": 10, \"sMin\": 100, \"vMin\": 60}");
        MethodHarness h = started(segmenting(Map.of("red", wrapping)));
        h.push("image", bgrWithRectangle(40, 40, new int[] {90, 90, 90}, red, 5, 5, 10, 10));
        assertThat(blobList(h.last("blobs"))).hasSize(1);
        h.push("image", bgrWithRectangle(40, 40, new int[] {90, 90, 90}, crimson, 5, 5, 10, 10));
        assertThat(blobList(h.last("blobs"))).hasSize(1);

        ColorRange between = ParamsJson.of(ColorRange.class, "{\"hMin\": 10, \"hMax\": 170, \"sMin\": 100, \"vMin\": 60}");
        MethodHarness notWrapping = started(segmenting(Map.of("red", between)));
        notWrapping.push("image", bgrWithRectangle(40, 40, new int[] {90, 90, 90}, red, 5, 5, 10, 10));
        assertThat(blobList(notWrapping.last("blobs"))).isEmpty();
        assertThat(wrapping.contains(2, 200, 200)).isTrue();
        assertThat(wrapping.contains(172, 200, 200)).isTrue();
        assertThat(wrapping.contains(90, 200, 200)).isFalse();
    }

    @Test
    void blobsOfSeveralClassesComeLargestFirstAndSmallOnesAreDropped() {
        Map<String, ColorRange> colors = new java.util.LinkedHashMap<>();
        colors.put("pink", ColorRange.pink());
        colors.put("blue", ParamsJson.of(ColorRange.class, "{\"hMin\": 100, \"hMax\": 130, \"sMin\": 100, \"vMin\": 60}"));
        MethodHarness h = started(new ImageSegmentationParams(colors, 20, 0, 0, ImageSegmentationParams.defaults().maxBlobs()));
        byte[] data = bgrWithRectangle(80, 60, new int[] {200, 200, 200}, new int[] {180, 105, 255}, 2, 2, 6, 6).data();
        paint(data, 80, new int[] {200, 60, 40}, 30, 20, 20, 20);   // blue, 400 px
        paint(data, 80, new int[] {200, 60, 40}, 70, 50, 4, 4);     // blue speck, 16 px: below minAreaPx
        h.push("image", ImageFrame.wrap(80, 60, "bgr8", data));
        JsonNode blobs = blobList(h.last("blobs"));
        assertThat(blobs).hasSize(2);
        assertThat(blobs.get(0).get("label").asText()).isEqualTo("blue");
        assertThat(blobs.get(0).get("area").asInt()).isEqualTo(400);
        assertThat(blobs.get(1).get("label").asText()).isEqualTo("pink");
        RecordValue largest = (RecordValue) h.last("largest");
        assertThat(largest.text("label")).isEqualTo("pink");
        assertThat(largest.number("area")).isEqualTo(36);
    }

    private static void paint(byte[] bgr, int w, int[] c, int rx, int ry, int rw, int rh) {
        for (int y = ry; y < ry + rh; y++) {
            for (int x = rx; x < rx + rw; x++) {
                int at = (y * w + x) * 3;
                bgr[at] = (byte) c[0];
                bgr[at + 1] = (byte) c[1];
                bgr[at + 2] = (byte) c[2];
            }
        }
    }

    @Test
    void methodIsNotReadyUntilOpenCvIsLoadedAndKeepsTheFrameThatCameMeanwhile() {
        MethodHarness h = MethodHarness.started("seg", new ImageSegmentation(ImageSegmentationParams.defaults()));
        assertThat(h.ready()).isFalse();
        assertThat(h.readinessDetail()).contains("loading");
        h.push("image", bgrWithRectangle(32, 32, new int[] {0, 0, 0}, new int[] {180, 105, 255}, 4, 4, 8, 8));
        assertThat(h.values("blobs")).isEmpty();
        h.runBackground();
        assertThat(h.ready()).isTrue();
        assertThat(blobList(h.last("blobs"))).hasSize(1);
    }

    @Test
    void framesArrivingWhileOneIsSegmentedAreDroppedExceptTheNewest() {
        ImageSegmentation method = new ImageSegmentation(ImageSegmentationParams.defaults());
        MethodHarness h = MethodHarness.started("seg", method);
        h.runBackground();
        for (int i = 0; i < 4; i++) {
            h.push("image", bgrWithRectangle(32, 32, new int[] {0, 0, 0}, new int[] {180, 105, 255}, i, 0, 8, 8),
                    1_000_000L * (i + 1));
        }
        h.runBackground();
        assertThat(h.samples("blobs")).extracting(s -> s.sourceMicros()).containsExactly(1_000_000L, 4_000_000L);
        assertThat(h.samples("blobs")).extracting(s -> ((RecordValue) s.payload()).get("blobs").get(0).get("x").asInt())
                .containsExactly(0, 3);
        assertThat(method.droppedFrames()).isEqualTo(2);
    }

    @Test
    void unreadableFrameIsSkippedAndTheNextOneIsSegmented() {
        ImageSegmentation method = new ImageSegmentation(ImageSegmentationParams.defaults());
        MethodHarness h = MethodHarness.started("seg", method).runBackgroundAtOnce();
        h.push("image", ImageFrame.of(32, 32, "jpeg", new byte[] {(byte) 0xff, (byte) 0xd8, 1, 2, 3, 4}));
        h.push("image", ImageFrame.of(32, 32, "tiff", new byte[] {1, 2, 3}));
        assertThat(h.values("blobs")).isEmpty();
        assertThat(method.unreadableFrames()).isEqualTo(2);
        h.push("image", bgrWithRectangle(32, 32, new int[] {0, 0, 0}, new int[] {180, 105, 255}, 4, 4, 8, 8));
        assertThat(h.state()).isEqualTo(MethodState.RUNNING);
        assertThat(blobList(h.last("blobs"))).hasSize(1);
    }

    @Test
    void grayFramesHaveNoColourAndGiveNoBlobs() {
        MethodHarness h = started(ImageSegmentationParams.defaults());
        byte[] gray = new byte[40 * 30];
        java.util.Arrays.fill(gray, (byte) 200);
        h.push("image", ImageFrame.wrap(40, 30, "gray8", gray));
        assertThat(blobList(h.last("blobs"))).isEmpty();
        assertThat(((RecordValue) h.last("blobs")).number("width")).isEqualTo(40);
    }

    @Test
    void paramsBindFromConfigJsonAndKeepTheOrderOfTheClasses() throws Exception {
        ImageSegmentationParams p = ParamsJson.of(ImageSegmentationParams.class,
                "{\"colors\": {\"orange\": {\"hMin\": 5, \"hMax\": 20}, \"pink\": {\"sMin\": 100}}, \"minAreaPx\": 30}");
        assertThat(p.colors().keySet()).containsExactly("orange", "pink");
        assertThat(p.firstLabel()).isEqualTo("orange");
        assertThat(p.colors().get("pink")).isEqualTo(new ColorRange(145, 175, 100, 255, 60, 255));
        assertThat(p.minAreaPx()).isEqualTo(30);
        assertThatThrownBy(() -> new ColorRange(10, 20, 200, 100, 0, 255)).hasMessageContaining("sMin");
        assertThatThrownBy(() -> ParamsJson.of(ImageSegmentationParams.class, "{\"colors\": {\"x\": {\"hMin\": 180}}}"))
                .hasMessageContaining("$.params.colors.x.hMin: must be within [0, 179], was 180");
        assertThatThrownBy(() -> ParamsJson.of(ImageSegmentationParams.class, "{\"colors\": {}}"))
                .hasMessageContaining("colors");
    }

    @Test
    void typeIsFoundByNameThroughDiscovery() {
        var provider = PluginRegistry.discover().method("image-segmentation").orElseThrow();
        assertThat(provider.layers()).containsExactly(Layer.PROCESSING);
        assertThat(provider.paramsType()).isEqualTo(ImageSegmentationParams.class);
    }
}
