package org.habla.methods.vision;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RadialGradientPaint;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.List;
import java.util.Random;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.MemoryCacheImageOutputStream;
import org.habla.sample.ImageFrame;

/**
 * Renders what a level pinhole camera sees in a small room, as JPEG frames: a floor, walls of various
 * colours, optionally the pink ball, and pixel noise. Robot frame: x forward, y left, z up; the camera
 * sits at height {@code cameraHeightM} above the origin and looks along x.
 */
final class CameraScene {

    static final double HFOV_RAD = 0.993;
    static final double BALL_RADIUS_M = 0.05;
    static final Color BALL = new Color(255, 105, 180);
    static final List<Color> WALLS = List.of(new Color(232, 230, 224), new Color(170, 172, 176),
            new Color(70, 110, 200), new Color(80, 170, 90), new Color(230, 210, 80), new Color(210, 190, 160),
            new Color(230, 140, 50), new Color(120, 70, 190), new Color(200, 40, 40), new Color(40, 40, 45));

    private final int width;
    private final int height;
    private final double cameraHeightM;
    private final double focalPx;

    CameraScene(int width, int height, double cameraHeightM) {
        this.width = width;
        this.height = height;
        this.cameraHeightM = cameraHeightM;
        this.focalPx = width / 2.0 / Math.tan(HFOV_RAD / 2);
    }

    /** Image column of a point (continuous, 0 at the left edge of the first pixel). */
    double u(double xM, double yM) {
        return width / 2.0 - focalPx * yM / xM;
    }

    /** Image row of a point (continuous, 0 at the top edge of the first row). */
    double v(double xM, double zM) {
        return height / 2.0 - focalPx * (zM - cameraHeightM) / xM;
    }

    /** The ball's projected centre as a pixel index (pixel i spans [i, i+1), so its centre is i + 0.5). */
    Point2D.Double projectedBallCentre(double xM, double yM) {
        return new Point2D.Double(u(xM, yM) - 0.5, v(xM, BALL_RADIUS_M) - 0.5);
    }

    /** Projected radius of the ball, in pixels. */
    double ballRadiusPx(double xM) {
        return focalPx * BALL_RADIUS_M / xM;
    }

    /** Largest |y| at distance x that keeps the whole ball in the frame, with a margin. */
    double maxLateralM(double xM) {
        return (width / 2.0 - 3) * xM / focalPx - BALL_RADIUS_M * 1.2;
    }

    /** A JPEG frame of a random room, with the ball at (xM, yM) when {@code ball} is set. */
    ImageFrame render(Random random, boolean ball, double xM, double yM) {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        double wallDistM = 2.8 + random.nextDouble() * 2;
        double wallTopV = v(wallDistM, 0.6);
        double wallFootV = v(wallDistM, 0);
        g.setColor(new Color(150, 150, 155));
        g.fillRect(0, 0, width, height);
        int segments = 2 + random.nextInt(4);
        double at = 0;
        for (int i = 0; i < segments; i++) {
            double w = i == segments - 1 ? width - at : width * (0.15 + random.nextDouble() * 0.4);
            g.setColor(WALLS.get(random.nextInt(WALLS.size())));
            g.fill(new java.awt.geom.Rectangle2D.Double(at, wallTopV, w, wallFootV - wallTopV));
            at += w;
        }
        g.setColor(new Color(125, 104, 84));
        g.fill(new java.awt.geom.Rectangle2D.Double(0, wallFootV, width, height - wallFootV));
        g.setColor(new Color(95, 80, 64));
        for (int i = 0; i < 6; i++) {
            double y = wallFootV + (height - wallFootV) * random.nextDouble();
            g.fill(new java.awt.geom.Rectangle2D.Double(0, y, width, 1 + random.nextInt(2)));
        }
        if (ball) {
            double cu = u(xM, yM);
            double cv = v(xM, BALL_RADIUS_M);
            double r = ballRadiusPx(xM);
            g.setPaint(new RadialGradientPaint(new Point2D.Double(cu - r * 0.35, cv - r * 0.35), (float) (r * 1.4),
                    new float[] {0f, 1f}, new Color[] {new Color(255, 140, 200), new Color(175, 62, 120)}));
            g.fill(new Ellipse2D.Double(cu - r, cv - r, 2 * r, 2 * r));
        }
        g.dispose();
        addNoise(img, random, 6);
        return ImageFrame.wrap(width, height, "jpeg", jpeg(img, 0.8f));
    }

    private static void addNoise(BufferedImage img, Random random, double sigma) {
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                int rgb = img.getRGB(x, y);
                int r = clamp(((rgb >> 16) & 0xff) + random.nextGaussian() * sigma);
                int gr = clamp(((rgb >> 8) & 0xff) + random.nextGaussian() * sigma);
                int b = clamp((rgb & 0xff) + random.nextGaussian() * sigma);
                img.setRGB(x, y, (r << 16) | (gr << 8) | b);
            }
        }
    }

    private static int clamp(double v) {
        return (int) Math.max(0, Math.min(255, Math.round(v)));
    }

    static byte[] jpeg(BufferedImage img, float quality) {
        ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (MemoryCacheImageOutputStream out = new MemoryCacheImageOutputStream(bytes)) {
            writer.setOutput(out);
            ImageWriteParam p = writer.getDefaultWriteParam();
            p.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            p.setCompressionQuality(quality);
            writer.write(null, new IIOImage(img, null, null), p);
        } catch (IOException e) {
            throw new IllegalStateException(e);
        } finally {
            writer.dispose();
        }
        return bytes.toByteArray();
    }
}
