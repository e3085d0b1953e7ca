package org.habla.sim.aibo;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;

/**
 * A pinhole camera with the ERS-7's field of view (56.9° × 45.2°) that renders a {@link CameraView}:
 * each pixel's ray is traced to the nearest of the floor, the walls and the ball, and shaded by distance
 * and by the angle it meets the surface. The image is a Java2D {@link BufferedImage}, ready for JPEG.
 *
 * <p>Image coordinates: origin top-left, u to the right, v down; a world point straight ahead lands in
 * the centre. {@link #project} gives the pixel where a point appears, the same geometry the renderer
 * uses.
 */
public final class PinholeCamera {

    public static final double HFOV_RAD = 0.993;
    public static final double VFOV_RAD = 0.789;

    static final int FLOOR_RGB = 0x3c6e3c;
    static final int WALL_RGB = 0xd8ccb0;
    static final int ROOM_RGB = 0x404858;

    private final int width;
    private final int height;
    private final double fx;
    private final double fy;

    public PinholeCamera(int width, int height) {
        this.width = width;
        this.height = height;
        this.fx = width / 2.0 / Math.tan(HFOV_RAD / 2);
        this.fy = height / 2.0 / Math.tan(VFOV_RAD / 2);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** The pixel {@code [u, v]} where the world point appears, or null when it is behind the camera. */
    public double[] project(CameraView.CameraPose c, double x, double y, double z) {
        double[] p = toCamera(c, x - c.xM(), y - c.yM(), z - c.zM());
        if (p[0] <= 1e-9) {
            return null;
        }
        return new double[] {width / 2.0 - fx * p[1] / p[0], height / 2.0 - fy * p[2] / p[0]};
    }

    /** Renders the view. */
    public BufferedImage render(CameraView view) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        int[] pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        double[][] walls = view.walls().toArray(double[][]::new);
        CameraView.CameraPose c = view.camera();
        double cy = Math.cos(c.yawRad());
        double sy = Math.sin(c.yawRad());
        double cp = Math.cos(c.pitchRad());
        double sp = Math.sin(c.pitchRad());
        for (int v = 0; v < height; v++) {
            double up = (height / 2.0 - (v + 0.5)) / fy;
            for (int u = 0; u < width; u++) {
                double left = (width / 2.0 - (u + 0.5)) / fx;
                // camera frame (forward, left, up) → pitch about the left axis → yaw about the vertical
                double f = cp - up * sp;
                double z = sp + up * cp;
                double dx = f * cy - left * sy;
                double dy = f * sy + left * cy;
                pixels[v * width + u] = shade(view, walls, c, dx, dy, z);
            }
        }
        return image;
    }

    /** The colour seen along the ray (dx, dy, dz) from the camera. */
    private static int shade(CameraView view, double[][] walls, CameraView.CameraPose c, double dx, double dy,
            double dz) {
        double norm = Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx /= norm;
        dy /= norm;
        dz /= norm;
        double best = Double.POSITIVE_INFINITY;
        int colour = ROOM_RGB;
        if (dz < -1e-9) {
            best = -c.zM() / dz;
            double fx = c.xM() + best * dx;
            double fy = c.yM() + best * dy;
            // a faint carpet pattern gives the floor texture without hiding the ball
            boolean tile = (Math.floorMod((long) Math.floor(fx / 0.25), 2) ^ Math.floorMod((long) Math.floor(fy / 0.25),
                    2)) == 0;
            colour = scale(FLOOR_RGB, (tile ? 1.0 : 0.9) * fade(best));
        }
        for (double[] w : walls) {
            double t = wallHit(c.xM(), c.yM(), dx, dy, w);
            if (t > 0 && t < best) {
                double hz = c.zM() + t * dz;
                if (hz >= 0 && hz <= view.wallHeightM()) {
                    best = t;
                    double wx = w[2] - w[0];
                    double wy = w[3] - w[1];
                    double len = Math.hypot(wx, wy);
                    double facing = Math.abs((dx * wy - dy * wx) / len);
                    colour = scale(WALL_RGB, (0.55 + 0.45 * facing) * fade(t));
                }
            }
        }
        CameraView.Ball b = view.ball();
        if (b != null) {
            double t = sphereHit(c, dx, dy, dz, b);
            if (t > 0 && t < best) {
                double nx = (c.xM() + t * dx - b.xM()) / b.radiusM();
                double ny = (c.yM() + t * dy - b.yM()) / b.radiusM();
                double nz = (c.zM() + t * dz - b.radiusM()) / b.radiusM();
                double light = Math.max(0, -(nx * dx + ny * dy + nz * dz)) * 0.5 + Math.max(0, nz) * 0.2 + 0.45;
                colour = scale(b.rgb(), Math.min(1.0, light));
            }
        }
        return colour;
    }

    /** The ray parameter where the horizontal ray meets the wall segment, or -1. */
    static double wallHit(double ox, double oy, double dx, double dy, double[] w) {
        double ex = w[2] - w[0];
        double ey = w[3] - w[1];
        double den = dx * ey - dy * ex;
        if (Math.abs(den) < 1e-12) {
            return -1;
        }
        double qx = w[0] - ox;
        double qy = w[1] - oy;
        double t = (qx * ey - qy * ex) / den;
        double s = (qx * dy - qy * dx) / den;
        return s >= 0 && s <= 1 ? t : -1;
    }

    /** The ray parameter of the first hit on the ball (unit direction), or -1. */
    static double sphereHit(CameraView.CameraPose c, double dx, double dy, double dz, CameraView.Ball b) {
        double ox = c.xM() - b.xM();
        double oy = c.yM() - b.yM();
        double oz = c.zM() - b.radiusM();
        double half = ox * dx + oy * dy + oz * dz;
        double disc = half * half - (ox * ox + oy * oy + oz * oz - b.radiusM() * b.radiusM());
        if (disc < 0) {
            return -1;
        }
        double t = -half - Math.sqrt(disc);
        return t > 0 ? t : -1;
    }

    private double[] toCamera(CameraView.CameraPose c, double x, double y, double z) {
        double cy = Math.cos(c.yawRad());
        double sy = Math.sin(c.yawRad());
        double cp = Math.cos(c.pitchRad());
        double sp = Math.sin(c.pitchRad());
        double h = x * cy + y * sy;
        double left = -x * sy + y * cy;
        double forward = h * cp + z * sp;
        double up = -h * sp + z * cp;
        return new double[] {forward, left, up};
    }

    private static double fade(double distanceM) {
        return 1.0 / (1.0 + 0.08 * distanceM);
    }

    private static int scale(int rgb, double k) {
        int r = (int) Math.round(((rgb >> 16) & 0xff) * k);
        int g = (int) Math.round(((rgb >> 8) & 0xff) * k);
        int b = (int) Math.round((rgb & 0xff) * k);
        return (r << 16) | (g << 8) | b;
    }
}
