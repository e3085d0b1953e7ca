package org.habla.methods.sensors;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import javax.imageio.ImageIO;
import org.habla.driver.ChannelDescriptor;
import org.habla.method.MethodHarness;
import org.habla.methods.geometry.CameraModel;
import org.habla.sample.ImageFrame;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

class CameraTest {

    private static ImageFrame jpeg(int w, int h) throws Exception {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setColor(new Color(255, 105, 180));
        g.fillOval(w / 3, h / 3, w / 4, w / 4);
        g.dispose();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(img, "jpeg", out);
        return ImageFrame.of(w, h, "jpeg", out.toByteArray());
    }

    private static ChannelDescriptor channel() {
        ObjectNode m = JsonNodeFactory.instance.objectNode().put("hfovRad", 0.993).put("vfovRad", 0.789)
                .put("width", 104).put("height", 80).put("heightM", 0.2).put("mount", "head");
        return ChannelDescriptor.reading("camera", PayloadKind.IMAGE, "").withMetadata(m);
    }

    @Test
    void framesPassWithTheCameraDescribedFromMetadataAndTheRealFrameSize() throws Exception {
        MethodHarness h = MethodHarness.of("camera", new Camera(CameraParams.defaults())).wireChannel("image", channel()).start();
        ImageFrame small = jpeg(104, 80);
        h.push("image", small).push("image", small);
        assertThat(h.values("image")).containsExactly(small, small);
        assertThat(h.values("camera")).hasSize(1);
        CameraModel cam = CameraModel.fromJson(((RecordValue) h.last("camera")).json(), null).orElseThrow();
        assertThat(cam).isEqualTo(new CameraModel(0.993, 0.789, 104, 80, 0.2));
        h.push("image", jpeg(208, 160));
        assertThat(h.values("camera")).hasSize(2);
        assertThat(((RecordValue) h.last("camera")).number("width")).isEqualTo(208);
    }

    @Test
    void damagedFramesAreDroppedAndCounted() throws Exception {
        Camera camera = new Camera(CameraParams.defaults());
        MethodHarness h = MethodHarness.of("camera", camera).wireChannel("image", channel()).start();
        h.push("image", ImageFrame.of(104, 80, "jpeg", new byte[] {1, 2, 3, 4, 5}));
        h.push("image", ImageFrame.of(104, 80, "png", new byte[] {(byte) 0xFF, (byte) 0xD8, (byte) 0xFF, 0}));
        h.push("image", ImageFrame.of(104, 80, "jpeg", new byte[0]));
        ImageFrame good = jpeg(104, 80);
        h.push("image", good);
        assertThat(h.values("image")).containsExactly(good);
        assertThat(camera.malformed()).isEqualTo(3);
    }

    @Test
    void maxFpsKeepsEveryThirdFrameOfA30FpsStreamCappedAt10() throws Exception {
        Camera camera = new Camera(new CameraParams(10.0, 1.0, 0.8, null));
        MethodHarness h = MethodHarness.started("camera", camera);
        ImageFrame f = jpeg(52, 40);
        long t0 = h.nowMicros();
        for (int i = 0; i < 90; i++) {
            h.push("image", f, t0 + Math.round(i * 1_000_000 / 30.0));
        }
        assertThat(h.values("image")).hasSize(30);
        assertThat(camera.skipped()).isEqualTo(60);
        assertThat(((RecordValue) h.last("camera")).number("hfovRad")).isEqualTo(1.0);
    }
}
