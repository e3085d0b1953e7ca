package org.habla.sim.pioneer;

import java.util.Random;
import org.habla.sim.world.Pose2;
import org.habla.sim.world.Target;
import org.habla.sim.world.World;

/**
 * What one sonar transducer hears: the nearest echo within its 30° beam (a fan of rays cast in the world), plus
 * Gaussian noise, clipped to the sonar's 0.1–5 m and reported as 5 m when nothing is in range.
 */
final class SonarModel {

    /** Rays cast across one beam. */
    static final int RAYS_PER_BEAM = 5;

    private final World world;
    private final Random random;
    private final double noiseM;

    SonarModel(World world, Random random, double noiseM) {
        this.world = world;
        this.random = random;
        this.noiseM = noiseM;
    }

    /** The exact range (no noise) a transducer on a robot at {@code robot} measures. */
    static double trueRange(World world, Target target, Pose2 robot, P2dx.Transducer t) {
        Pose2 at = robot.moved(t.xM(), t.yM(), t.thetaRad());
        double best = P2dx.SONAR_MAX_RANGE_M;
        for (int i = 0; i < RAYS_PER_BEAM; i++) {
            double offset = P2dx.SONAR_BEAM_RAD * (i / (double) (RAYS_PER_BEAM - 1) - 0.5);
            best = Math.min(best, world.rangeAlong(at.xM(), at.yM(), at.thetaRad() + offset, P2dx.SONAR_MAX_RANGE_M,
                    target));
        }
        return best;
    }

    /** One noisy reading in metres. */
    double read(Target target, Pose2 robot, P2dx.Transducer t) {
        double r = trueRange(world, target, robot, t);
        if (r >= P2dx.SONAR_MAX_RANGE_M) {
            return P2dx.SONAR_MAX_RANGE_M;
        }
        double noisy = r + random.nextGaussian() * noiseM;
        return Math.max(P2dx.SONAR_MIN_RANGE_M, Math.min(P2dx.SONAR_MAX_RANGE_M, noisy));
    }
}
