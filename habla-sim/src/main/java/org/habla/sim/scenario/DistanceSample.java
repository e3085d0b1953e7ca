package org.habla.sim.scenario;

/**
 * The robot's distance to the target at one moment of an episode.
 *
 * @param tS        seconds since the episode began (world time)
 * @param distanceM distance to the target's edge, metres (≥ 0)
 */
public record DistanceSample(double tS, double distanceM) {

    public DistanceSample {
        if (!Double.isFinite(tS) || tS < 0) {
            throw new IllegalArgumentException("a sample's time must be finite and >= 0 s, got " + tS);
        }
        if (!Double.isFinite(distanceM) || distanceM < 0) {
            throw new IllegalArgumentException("a sample's distance must be finite and >= 0 m, got " + distanceM);
        }
    }
}
