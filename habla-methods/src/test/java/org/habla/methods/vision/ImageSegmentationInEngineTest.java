package org.habla.methods.vision;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.graph.EngineClock;
import org.habla.graph.MethodGraph;
import org.habla.method.Input;
import org.habla.method.Output;
import org.habla.net.ControlPoint;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.ImageFrame;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * image-segmentation inside the real engine, loaded by name from a config: its own thread, the engine's
 * background pool, frames arriving faster than they are segmented.
 */
@Timeout(60)
class ImageSegmentationInEngineTest {

    private static final String CONFIG = """
            {"system": "vision-test", "status": {"port": 0},
             "methods": [
               {"id": "frames", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
                "params": {"kind": "image", "delivery": "queue", "capacity": 256}, "expose": {"port": 7001}},
               {"id": "segment", "type": "image-segmentation", "layer": "processing", "inputs": {"image": "frames.out"},
                "params": {"colors": {"pink": {"hMin": 150, "hMax": 175}, "blue": {"hMin": 100, "hMax": 130}},
                           "openPx": 0, "minAreaPx": 4}},
               {"id": "found", "type": "pass-through", "layer": "virtual", "inputs": {"in": "segment.largest"},
                "params": {"kind": "record", "delivery": "queue", "capacity": 256}, "expose": {"port": 7002}}
             ]}
            """;

    /** A black bgr8 frame with a pink square whose left edge is at column {@code x}. */
    private static ImageFrame frameWithSquareAt(int x) {
        int w = 160;
        int h = 120;
        byte[] bgr = new byte[w * h * 3];
        for (int row = 40; row < 56; row++) {
            for (int col = x; col < x + 16; col++) {
                int at = (row * w + col) * 3;
                bgr[at] = (byte) 180;
                bgr[at + 1] = (byte) 105;
                bgr[at + 2] = (byte) 255;
            }
        }
        return ImageFrame.wrap(w, h, "bgr8", bgr);
    }

    private static ControlPoint point(MethodGraph g, String name) {
        return g.controlPoints().stream().filter(p -> p.name().equals(name)).findFirst().orElseThrow();
    }

    @Test
    void framesFasterThanSegmentationAreThinnedToTheNewestInOrderWithTheirSourceTimes() throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig config = new ConfigLoader(registry).parse(CONFIG);
        try (MethodGraph graph = MethodGraph.build(config, registry, EngineClock.system())) {
            graph.start();
            List<Sample> found = new CopyOnWriteArrayList<>();
            point(graph, "found").subscribe(new ControlPoint.Listener() {
                @Override
                public void onSample(Output<?> output, Sample sample) {
                    found.add(sample);
                }

                @Override
                public void onStale(boolean stale, String why) {
                }
            });
            ControlPoint frames = point(graph, "frames");
            Input<?> in = frames.controlInputs().get(0);
            frames.write(in, frameWithSquareAt(0));   // waits while OpenCV loads, then is segmented
            long ready = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (System.nanoTime() < ready && found.isEmpty()) {
                Thread.sleep(10);
            }
            assertThat(found).as("the first frame, once OpenCV is loaded").hasSize(1);
            int count = 120;
            for (int i = 1; i < count; i++) {
                frames.write(in, frameWithSquareAt(i));
            }
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (System.nanoTime() < end && (found.isEmpty() || lastX(found) != count - 1)) {
                Thread.sleep(10);
            }
            assertThat(found).isNotEmpty();
            assertThat(lastX(found)).as("the newest frame is always segmented").isEqualTo(count - 1);
            List<Integer> xs = found.stream().map(s -> ((RecordValue) s.payload()).get("x").asInt()).toList();
            assertThat(xs).isSorted().doesNotHaveDuplicates().hasSizeLessThanOrEqualTo(count);
            for (Sample s : found) {
                RecordValue r = (RecordValue) s.payload();
                assertThat(r.get("seen").asBoolean()).isTrue();
                assertThat(r.text("label")).isEqualTo("pink");
                assertThat(r.number("cx")).isEqualTo(r.number("x") + 7.5);
                assertThat(r.number("area")).isEqualTo(256);
            }
            for (int i = 1; i < found.size(); i++) {
                assertThat(found.get(i).sourceMicros()).isGreaterThanOrEqualTo(found.get(i - 1).sourceMicros());
            }
            System.out.printf("image-segmentation in the engine: %d of %d frames segmented, the rest dropped as stale%n",
                    found.size(), count);
            assertThat(graph.status().toString()).contains("segment");
        }
    }

    private static int lastX(List<Sample> found) {
        return ((RecordValue) found.get(found.size() - 1).payload()).get("x").asInt();
    }
}
