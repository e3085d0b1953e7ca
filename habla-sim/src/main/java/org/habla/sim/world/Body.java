package org.habla.sim.world;

/**
 * A round robot body moving on the floor: it takes velocity commands in its own frame (forward, leftward,
 * counter-clockwise turn), reaches them within its acceleration limits, and stops translating when it would
 * push into a wall or the target — then it is {@link #stalled()} and knows where the contact is. Turning on the
 * spot is always allowed (a circle turning in place cannot hit anything). Thread-safe: commands come from a
 * robot's protocol threads, steps from the sim clock.
 */
public final class Body {

    /** The body's size and how hard it can speed up and slow down. */
    public record Limits(double radiusM, double maxVelMps, double maxRotVelRadps, double accelMps2,
                         double rotAccelRadps2, double decelMps2, double rotDecelRadps2) {
        public Limits {
            for (double v : new double[] {radiusM, maxVelMps, maxRotVelRadps, accelMps2, rotAccelRadps2, decelMps2,
                rotDecelRadps2}) {
                if (!(v > 0) || !Double.isFinite(v)) {
                    throw new IllegalArgumentException("body limits must be positive numbers: " + v);
                }
            }
        }

        /** Limits that slow down as hard as they speed up. */
        public Limits(double radiusM, double maxVelMps, double maxRotVelRadps, double accelMps2, double rotAccelRadps2) {
            this(radiusM, maxVelMps, maxRotVelRadps, accelMps2, rotAccelRadps2, accelMps2, rotAccelRadps2);
        }
    }

    private final Limits limits;
    private Pose2 pose;
    private double wantVx;
    private double wantVy;
    private double wantW;
    private double vx;
    private double vy;
    private double w;
    private boolean stalled;
    private double contactBearingRad = Double.NaN;

    public Body(Limits limits, Pose2 start) {
        this.limits = limits;
        this.pose = start;
    }

    public Limits limits() {
        return limits;
    }

    /** Asks for these velocities (robot frame); clamped to the body's maximum speeds. */
    public synchronized void command(double forwardMps, double leftMps, double turnRadps) {
        wantVx = clamp(finite(forwardMps), limits.maxVelMps());
        wantVy = clamp(finite(leftMps), limits.maxVelMps());
        wantW = clamp(finite(turnRadps), limits.maxRotVelRadps());
    }

    /** Stops at once, without ramping (an emergency stop, or the robot being picked up). */
    public synchronized void halt() {
        wantVx = wantVy = wantW = 0;
        vx = vy = w = 0;
    }

    /** Puts the body somewhere, at rest. */
    public synchronized void placeAt(Pose2 p) {
        pose = p;
        halt();
        stalled = false;
        contactBearingRad = Double.NaN;
    }

    /** Advances the body by {@code dtS} seconds in {@code world} with the target at {@code where}. */
    public synchronized void step(double dtS, World world, Target where) {
        vx = ramp(vx, wantVx, limits.accelMps2() * dtS, limits.decelMps2() * dtS);
        vy = ramp(vy, wantVy, limits.accelMps2() * dtS, limits.decelMps2() * dtS);
        w = ramp(w, wantW, limits.rotAccelRadps2() * dtS, limits.rotDecelRadps2() * dtS);
        // Integrate along the arc's mid-heading: exact enough for 10 ms steps.
        Pose2 mid = new Pose2(pose.xM(), pose.yM(), pose.thetaRad() + w * dtS / 2);
        Pose2 moved = mid.moved(vx * dtS, vy * dtS, w * dtS / 2);
        double r = limits.radiusM();
        double before = world.clearance(pose.xM(), pose.yM(), where);
        double after = world.clearance(moved.xM(), moved.yM(), where);
        boolean translating = vx != 0 || vy != 0;
        if (translating && after < r && after < before) {
            // Go as far as the obstacle lets (to within a tenth of a millimetre), then stop.
            double lo = 0;
            double hi = 1;
            for (int i = 0; i < 16; i++) {
                double f = (lo + hi) / 2;
                double x = pose.xM() + f * (moved.xM() - pose.xM());
                double y = pose.yM() + f * (moved.yM() - pose.yM());
                if (world.clearance(x, y, where) >= r) {
                    lo = f;
                } else {
                    hi = f;
                }
            }
            pose = new Pose2(pose.xM() + lo * (moved.xM() - pose.xM()), pose.yM() + lo * (moved.yM() - pose.yM()),
                    moved.thetaRad());
            vx = vy = 0;
            stalled = true;
            contactBearingRad = Pose2.normalize(world.directionToNearest(pose.xM(), pose.yM(), where) - pose.thetaRad());
        } else {
            pose = moved;
            boolean touching = after < r + 1e-3;
            stalled = touching && (wantVx != 0 || wantVy != 0) && after <= before;
            contactBearingRad = touching
                    ? Pose2.normalize(world.directionToNearest(pose.xM(), pose.yM(), where) - pose.thetaRad())
                    : Double.NaN;
        }
    }

    public synchronized Pose2 pose() {
        return pose;
    }

    /** Current forward speed, m/s (robot frame). */
    public synchronized double forwardMps() {
        return vx;
    }

    /** Current leftward speed, m/s (robot frame). */
    public synchronized double leftMps() {
        return vy;
    }

    /** Current turn rate, rad/s, counter-clockwise positive. */
    public synchronized double turnRadps() {
        return w;
    }

    /** Whether the body is pushing against something and not getting anywhere. */
    public synchronized boolean stalled() {
        return stalled;
    }

    /** Bearing (robot frame, + left) of the obstacle the body touches, or NaN when it touches nothing. */
    public synchronized double contactBearingRad() {
        return contactBearingRad;
    }

    private static double ramp(double current, double wanted, double maxUp, double maxDown) {
        boolean slowing = current != 0 && (wanted * current < 0 || Math.abs(wanted) < Math.abs(current));
        double maxChange = slowing ? maxDown : maxUp;
        double d = wanted - current;
        return Math.abs(d) <= maxChange ? wanted : current + Math.signum(d) * maxChange;
    }

    private static double clamp(double v, double max) {
        return Math.max(-max, Math.min(max, v));
    }

    private static double finite(double v) {
        return Double.isFinite(v) ? v : 0;
    }
}
