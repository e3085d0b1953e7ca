package org.habla.sim.pioneer;

import java.util.Objects;
import org.habla.sim.world.World;

/**
 * How to run a simulated Pioneer: the world, the time scale, the random seed, the four ports (0 picks a free
 * one) and whether the teacher starts present.
 *
 * @param speed      sim time runs this many times faster than real time (≥ 1)
 * @param sonarNoiseM standard deviation of the sonar's range noise, metres
 */
public record PioneerSimOptions(World world, double speed, long seed, int arcosPort, int micPort, int keysPort,
                                int truthPort, boolean teacherOn, double sonarNoiseM) {

    public static final int DEFAULT_ARCOS_PORT = 8101;
    public static final int DEFAULT_MIC_PORT = 8110;
    public static final int DEFAULT_KEYS_PORT = 8111;
    public static final int DEFAULT_TRUTH_PORT = 8199;
    public static final double DEFAULT_SONAR_NOISE_M = 0.01;

    public PioneerSimOptions {
        Objects.requireNonNull(world, "world");
        if (!(speed >= 1) || !Double.isFinite(speed)) {
            throw new IllegalArgumentException("speed must be a number ≥ 1, was " + speed);
        }
        for (int p : new int[] {arcosPort, micPort, keysPort, truthPort}) {
            if (p < 0 || p > 65_535) {
                throw new IllegalArgumentException("a port must be in 0..65535, was " + p);
            }
        }
        if (!(sonarNoiseM >= 0)) {
            throw new IllegalArgumentException("sonarNoiseM must be ≥ 0, was " + sonarNoiseM);
        }
    }

    /** The built-in room on the default ports, real time, teacher present. */
    public static PioneerSimOptions defaults() {
        return new PioneerSimOptions(World.builtIn("pioneer-room"), 1, 1, DEFAULT_ARCOS_PORT, DEFAULT_MIC_PORT,
                DEFAULT_KEYS_PORT, DEFAULT_TRUTH_PORT, true, DEFAULT_SONAR_NOISE_M);
    }

    /** The given world on free ports at {@code speed}, teacher away: what a test wants. */
    public static PioneerSimOptions forTest(World world, double speed) {
        return new PioneerSimOptions(world, speed, 42, 0, 0, 0, 0, false, DEFAULT_SONAR_NOISE_M);
    }

    public PioneerSimOptions withTeacher(boolean on) {
        return new PioneerSimOptions(world, speed, seed, arcosPort, micPort, keysPort, truthPort, on, sonarNoiseM);
    }
}
