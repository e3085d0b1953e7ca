package org.habla.sim.world;

/**
 * A planar pose: position in metres in the world frame and heading in radians, counter-clockwise from +x,
 * always kept in (-π, π].
 */
public record Pose2(double xM, double yM, double thetaRad) {

    public Pose2 {
        if (!Double.isFinite(xM) || !Double.isFinite(yM) || !Double.isFinite(thetaRad)) {
            throw new IllegalArgumentException("a pose needs finite numbers, got " + xM + ", " + yM + ", " + thetaRad);
        }
        thetaRad = normalize(thetaRad);
    }

    /** The origin, heading along +x. */
    public static final Pose2 ORIGIN = new Pose2(0, 0, 0);

    /** An angle wrapped into (-π, π]. */
    public static double normalize(double angleRad) {
        double a = Math.IEEEremainder(angleRad, 2 * Math.PI);
        return a <= -Math.PI ? a + 2 * Math.PI : a;
    }

    /** Distance from this pose's position to a point. */
    public double distanceTo(double x, double y) {
        return Math.hypot(x - xM, y - yM);
    }

    /** Bearing of a point in this pose's frame: 0 straight ahead, positive to the left. */
    public double bearingTo(double x, double y) {
        return normalize(Math.atan2(y - yM, x - xM) - thetaRad);
    }

    /** This pose moved by a displacement given in its own frame ({@code forward}, {@code left}) and turned by {@code dTheta}. */
    public Pose2 moved(double forwardM, double leftM, double dThetaRad) {
        double c = Math.cos(thetaRad);
        double s = Math.sin(thetaRad);
        return new Pose2(xM + forwardM * c - leftM * s, yM + forwardM * s + leftM * c, thetaRad + dThetaRad);
    }

    /** The displacement from this pose to {@code other}, projected on this pose's heading (positive ahead). */
    public double forwardTo(Pose2 other) {
        return (other.xM - xM) * Math.cos(thetaRad) + (other.yM - yM) * Math.sin(thetaRad);
    }
}
