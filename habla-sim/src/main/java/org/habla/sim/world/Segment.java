package org.habla.sim.world;

/** A straight wall from ({@code x1}, {@code y1}) to ({@code x2}, {@code y2}), metres, world frame. */
public record Segment(double x1, double y1, double x2, double y2) {

    public Segment {
        if (!Double.isFinite(x1) || !Double.isFinite(y1) || !Double.isFinite(x2) || !Double.isFinite(y2)) {
            throw new IllegalArgumentException("a wall needs four finite numbers");
        }
        if (x1 == x2 && y1 == y2) {
            throw new IllegalArgumentException("a wall needs two distinct end points, got (" + x1 + ", " + y1 + ") twice");
        }
    }

    /**
     * How far a ray from ({@code ox}, {@code oy}) along the unit direction ({@code dx}, {@code dy}) travels before it
     * meets this wall, or {@code +∞} if it never does.
     */
    public double rayDistance(double ox, double oy, double dx, double dy) {
        double ex = x2 - x1;
        double ey = y2 - y1;
        double denom = dx * ey - dy * ex;
        if (Math.abs(denom) < 1e-12) {
            return Double.POSITIVE_INFINITY; // parallel: a grazing ray does not return an echo
        }
        double wx = x1 - ox;
        double wy = y1 - oy;
        double t = (wx * ey - wy * ex) / denom;
        double u = (wx * dy - wy * dx) / denom;
        return t >= 0 && u >= 0 && u <= 1 ? t : Double.POSITIVE_INFINITY;
    }

    /** The point of this wall closest to ({@code x}, {@code y}), as {@code {px, py}}. */
    public double[] closestPoint(double x, double y) {
        double ex = x2 - x1;
        double ey = y2 - y1;
        double u = ((x - x1) * ex + (y - y1) * ey) / (ex * ex + ey * ey);
        u = Math.max(0, Math.min(1, u));
        return new double[] {x1 + u * ex, y1 + u * ey};
    }

    /** Distance from ({@code x}, {@code y}) to the nearest point of this wall. */
    public double distanceTo(double x, double y) {
        double[] p = closestPoint(x, y);
        return Math.hypot(x - p[0], y - p[1]);
    }
}
