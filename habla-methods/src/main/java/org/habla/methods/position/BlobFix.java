package org.habla.methods.position;

import java.util.Optional;
import org.habla.methods.geometry.CameraModel;
import org.habla.methods.gaze.HeadPose;

/**
 * Locates a ball of known radius from the blob it makes in an image of a pinhole camera on a
 * pan-and-tilt head. Two estimates, in the robot frame (x forward, y left, z up, origin on the floor):
 *
 * <ul>
 *   <li><b>size</b>: the blob's angular size gives the range along the ray through its centre,
 *       range = radius / sin(half angle). It works at any head angle, which is why it is preferred.</li>
 *   <li><b>ground</b>: the ray through the blob's centre meets the plane at the ball's centre height
 *       (radius above the floor). It needs the camera to look down at the ball and is used when the blob
 *       is too small or cut by the image border to measure its size.</li>
 * </ul>
 *
 * The head pans about a vertical axis {@code cameraXM} ahead of the robot's origin; the lens sits
 * {@code lensForwardM} ahead of that axis in the pan direction, at the camera's height, and pitches by
 * tilt + nod (as if both joints turned about the lens).
 */
public final class BlobFix {

    /** Where the ball is and how that was found. */
    public record Fix(double xM, double yM, String method, Double groundRangeM) {
    }

    private final CameraModel camera;
    private final double radiusM;
    private final double cameraXM;
    private final double lensForwardM;
    private final double minRadiusPx;

    public BlobFix(CameraModel camera, double radiusM, double cameraXM, double lensForwardM, double minRadiusPx) {
        this.camera = camera;
        this.radiusM = radiusM;
        this.cameraXM = cameraXM;
        this.lensForwardM = lensForwardM;
        this.minRadiusPx = minRadiusPx;
    }

    /** Where the lens is in the robot frame with the head at {@code head}: {x, y, z}. */
    public double[] lens(HeadPose head) {
        return new double[] {cameraXM + lensForwardM * Math.cos(head.panRad()), lensForwardM * Math.sin(head.panRad()),
            camera.heightM()};
    }

    /**
     * The ball's centre seen as a blob centred at ({@code cx}, {@code cy}) with the bounding box
     * ({@code x}, {@code y}, {@code w}, {@code h}) in pixels, the head at {@code head}. Empty when
     * neither estimate is possible.
     */
    public Optional<Fix> locate(double cx, double cy, double x, double y, double w, double h, HeadPose head) {
        double[] dir = toRobot(camera.ray(cx, cy), head);
        double norm = Math.sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        double[] unit = {dir[0] / norm, dir[1] / norm, dir[2] / norm};
        double[] origin = lens(head);
        Double groundRange = null;
        double[] ground = null;
        if (unit[2] < -1e-3) {
            double t = (camera.heightM() - radiusM) / -unit[2];
            if (t > 0) {
                ground = new double[] {origin[0] + t * unit[0], origin[1] + t * unit[1]};
                groundRange = Math.hypot(ground[0], ground[1]);
            }
        }
        double halfAngle = halfAngle(cx, cy, x, y, w, h);
        if (halfAngle > 0 && (Math.max(w, h) / 2 >= minRadiusPx || ground == null)) {
            double range = radiusM / Math.sin(halfAngle);
            return Optional.of(new Fix(origin[0] + range * unit[0], origin[1] + range * unit[1], "size", groundRange));
        }
        if (ground != null) {
            return Optional.of(new Fix(ground[0], ground[1], "ground", groundRange));
        }
        return Optional.empty();
    }

    /**
     * Half the angle the ball subtends: the angle between the rays through the box's opposite edges
     * (along the centre row and the centre column), from the sides the image border did not cut.
     * The smaller of the two is kept when both are whole, as the blob of a ball off the axis is
     * stretched away from the image centre. 0 when no side is whole.
     */
    private double halfAngle(double cx, double cy, double x, double y, double w, double h) {
        boolean cutX = x <= 0.5 || x + w >= camera.width() - 0.5;
        boolean cutY = y <= 0.5 || y + h >= camera.height() - 0.5;
        double across = cutX || w <= 0 ? 0 : angleBetween(camera.ray(x, cy), camera.ray(x + w, cy));
        double down = cutY || h <= 0 ? 0 : angleBetween(camera.ray(cx, y), camera.ray(cx, y + h));
        if (across > 0 && down > 0) {
            return Math.min(across, down) / 2;
        }
        return Math.max(across, down) / 2;
    }

    private static double angleBetween(double[] a, double[] b) {
        double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        double na = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        double nb = Math.sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
        return Math.acos(Math.max(-1, Math.min(1, dot / (na * nb))));
    }

    /** A direction of the camera frame turned into the robot frame: pitch about y, then pan about z. */
    static double[] toRobot(double[] d, HeadPose head) {
        double p = head.pitchRad();
        double x1 = d[0] * Math.cos(p) - d[2] * Math.sin(p);
        double z1 = d[0] * Math.sin(p) + d[2] * Math.cos(p);
        double yaw = head.panRad();
        return new double[] {x1 * Math.cos(yaw) - d[1] * Math.sin(yaw), x1 * Math.sin(yaw) + d[1] * Math.cos(yaw), z1};
    }

    /** A direction of the robot frame turned into the camera frame: the inverse of {@link #toRobot}. */
    static double[] toCamera(double[] d, HeadPose head) {
        double yaw = -head.panRad();
        double x1 = d[0] * Math.cos(yaw) - d[1] * Math.sin(yaw);
        double y1 = d[0] * Math.sin(yaw) + d[1] * Math.cos(yaw);
        double p = -head.pitchRad();
        return new double[] {x1 * Math.cos(p) - d[2] * Math.sin(p), y1, x1 * Math.sin(p) + d[2] * Math.cos(p)};
    }
}
