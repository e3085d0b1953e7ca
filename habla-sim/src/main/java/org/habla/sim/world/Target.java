package org.habla.sim.world;

/**
 * The object the robot is taught to approach: a disc (a post for the Pioneer, a ball for the Aibo) seen from
 * above, centre in metres, world frame, with the colour a camera sees it in.
 */
public record Target(double xM, double yM, double radiusM, String color) {

    public Target {
        if (!Double.isFinite(xM) || !Double.isFinite(yM)) {
            throw new IllegalArgumentException("the target's position must be finite numbers");
        }
        if (!(radiusM > 0) || !Double.isFinite(radiusM)) {
            throw new IllegalArgumentException("the target's radiusM must be a positive number, was " + radiusM);
        }
        color = color == null || color.isBlank() ? "pink" : color;
    }

    /** The same object somewhere else. */
    public Target movedTo(double x, double y) {
        return new Target(x, y, radiusM, color);
    }

    /** Distance from ({@code x}, {@code y}) to the target's edge (negative inside). */
    public double surfaceDistance(double x, double y) {
        return Math.hypot(x - xM, y - yM) - radiusM;
    }

    /** How far a ray along the unit direction ({@code dx}, {@code dy}) travels before it meets the disc, or {@code +∞}. */
    public double rayDistance(double ox, double oy, double dx, double dy) {
        double fx = ox - xM;
        double fy = oy - yM;
        double b = fx * dx + fy * dy;
        double c = fx * fx + fy * fy - radiusM * radiusM;
        if (c <= 0) {
            return 0; // the ray starts inside the object
        }
        double disc = b * b - c;
        if (disc < 0) {
            return Double.POSITIVE_INFINITY;
        }
        double t = -b - Math.sqrt(disc);
        return t >= 0 ? t : Double.POSITIVE_INFINITY;
    }
}
