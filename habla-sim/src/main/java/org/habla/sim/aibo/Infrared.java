package org.habla.sim.aibo;

import java.util.SplittableRandom;
import org.habla.sim.world.Pose2;
import org.habla.sim.world.Segment;
import org.habla.sim.world.Target;
import org.habla.sim.world.World;

/**
 * The ERS-7's three infrared distance sensors by ray casting in three dimensions: the near (0.05–0.5 m)
 * and far (0.2–1.5 m) sensors in the nose turn and pitch with the head, the chest sensor (0.1–0.9 m)
 * looks forward and down. A ray ends on the floor, a wall (up to {@link Ers7Geometry#WALL_HEIGHT_M}) or
 * the ball (a sphere resting on the floor). Readings beyond a sensor's range read as its maximum, closer
 * ones as its minimum; noise is Gaussian with σ = {@link #NOISE_FLOOR_M} + {@link #NOISE_FRACTION} × d.
 */
public final class Infrared {

    public static final double[] MIN_M = {0.05, 0.2, 0.1};
    public static final double[] MAX_M = {0.5, 1.5, 0.9};
    static final double NOISE_FLOOR_M = 0.002;
    static final double NOISE_FRACTION = 0.01;

    private final SplittableRandom random;

    public Infrared(long seed) {
        this.random = new SplittableRandom(seed);
    }

    /** The noiseless distances [near, far, chest] in metres, before range limits. */
    public static double[] exact(World world, Target ball, Pose2 body, Ers7Body.HeadPose head) {
        Ers7Geometry.Ray nose = Ers7Geometry.nose(body, head);
        double d = cast(world, ball, nose);
        return new double[] {d, d, cast(world, ball, Ers7Geometry.chest(body))};
    }

    /** What the sensors read: the exact distances with noise, within each sensor's range. */
    public double[] read(World world, Target ball, Pose2 body, Ers7Body.HeadPose head) {
        double[] d = exact(world, ball, body, head);
        for (int i = 0; i < 3; i++) {
            double noisy = d[i] + gaussian() * (NOISE_FLOOR_M + NOISE_FRACTION * Math.min(d[i], MAX_M[i]));
            d[i] = Math.max(MIN_M[i], Math.min(MAX_M[i], noisy));
        }
        return d;
    }

    /** How far the ray travels to the floor, a wall or the ball; +∞ if it meets nothing. */
    public static double cast(World world, Target ball, Ers7Geometry.Ray r) {
        double cp = Math.cos(r.pitchRad());
        double sp = Math.sin(r.pitchRad());
        double hx = Math.cos(r.yawRad());
        double hy = Math.sin(r.yawRad());
        double best = sp < -1e-9 ? -r.zM() / sp : Double.POSITIVE_INFINITY;
        if (cp > 1e-9) {
            for (Segment w : world.walls()) {
                double t = w.rayDistance(r.xM(), r.yM(), hx, hy) / cp;
                double z = r.zM() + t * sp;
                if (t < best && z >= 0 && z <= Ers7Geometry.WALL_HEIGHT_M) {
                    best = t;
                }
            }
        }
        double t = PinholeCamera.sphereHit(new CameraView.CameraPose(r.xM(), r.yM(), r.zM(), 0, 0), cp * hx, cp * hy,
                sp, new CameraView.Ball(ball.xM(), ball.yM(), ball.radiusM(), 0));
        return t > 0 && t < best ? t : best;
    }

    private double gaussian() {
        double s = 0;
        for (int i = 0; i < 6; i++) {
            s += random.nextDouble();
        }
        return (s - 3.0) * Math.sqrt(2.0);
    }
}
