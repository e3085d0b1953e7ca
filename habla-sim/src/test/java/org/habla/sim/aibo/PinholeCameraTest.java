package org.habla.sim.aibo;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.awt.image.BufferedImage;
import java.util.List;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriter;
import org.junit.jupiter.api.Test;

/** The pinhole camera's geometry and its picture of the ball. */
class PinholeCameraTest {

    private static final CameraView.CameraPose LEVEL = new CameraView.CameraPose(0, 0, 0.2, 0, 0);

    @Test
    void aPointStraightAheadLandsInTheCentreAndTheFieldOfViewSpansTheImage() {
        PinholeCamera c = new PinholeCamera(104, 80);
        assertThat(c.project(LEVEL, 3, 0, 0.2)).containsExactly(new double[] {52, 40}, within(1e-9));
        double x = 2;
        double[] leftEdge = c.project(LEVEL, x, x * Math.tan(PinholeCamera.HFOV_RAD / 2), 0.2);
        assertThat(leftEdge[0]).isCloseTo(0, within(1e-9));
        double[] top = c.project(LEVEL, x, 0, 0.2 + x * Math.tan(PinholeCamera.VFOV_RAD / 2));
        assertThat(top[1]).isCloseTo(0, within(1e-9));
        assertThat(c.project(LEVEL, -1, 0, 0)).as("behind the camera").isNull();
    }

    @Test
    void pitchingDownMovesTheFloorPointUpInTheImageAndYawTurnsTheView() {
        PinholeCamera c = new PinholeCamera(208, 160);
        double[] level = c.project(LEVEL, 1, 0, 0);
        double[] down = c.project(new CameraView.CameraPose(0, 0, 0.2, 0, -0.2), 1, 0, 0);
        assertThat(down[1]).isLessThan(level[1]);
        double[] yawed = c.project(new CameraView.CameraPose(0, 0, 0.2, Math.PI / 2, 0), 0, 3, 0.2);
        assertThat(yawed).containsExactly(new double[] {104, 80}, within(1e-9));
    }

    private static CameraView.Ball view(int i) {
        return new CameraView.Ball(1, 0.002 * i, 0.05, 0xff50aa);
    }

    @Test
    void theRenderedBallSitsOnItsProjectionAtEveryResolution() throws Exception {
        List<double[]> walls = List.of(new double[] {4, -3, 4, 3});
        ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
        for (int skip = 1; skip <= 3; skip++) {
            PinholeCamera c = new PinholeCamera(RawCamServer.WIDTH_BY_SKIP[skip], RawCamServer.HEIGHT_BY_SKIP[skip]);
            for (double[] at : new double[][] {{0.8, 0.2}, {1.5, -0.4}, {0.5, 0.0}}) {
                CameraView view = new CameraView(walls, 0.5, new CameraView.Ball(at[0], at[1], 0.05, 0xff50aa),
                        LEVEL);
                BufferedImage image = c.render(view);
                double[] seen = TekkotsuServersTest.pinkCentroid(image);
                double[] expected = c.project(LEVEL, at[0], at[1], 0.05);
                assertThat(seen[2]).isGreaterThan(2);
                assertThat(seen[0]).isCloseTo(expected[0], within(1.0));
                assertThat(seen[1]).isCloseTo(expected[1], within(1.0));
            }
            int frames = 50;
            for (int i = 0; i < frames; i++) {
                RawCamServer.jpeg(writer, c.render(new CameraView(walls, 0.5, view(i), LEVEL)));
            }
            long start = System.nanoTime();
            for (int i = 0; i < frames; i++) {
                RawCamServer.jpeg(writer, c.render(new CameraView(walls, 0.5,
                        new CameraView.Ball(1, 0.1 * i / frames, 0.05, 0xff50aa), LEVEL)));
            }
            System.out.printf("camera %dx%d: %.2f ms a frame (after warm-up) to render and encode as JPEG%n", c.width(), c.height(),
                    (System.nanoTime() - start) / 1e6 / frames);
        }
        writer.dispose();
    }
}
