package org.habla.sim.scenario;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * The figures of a whole scenario run on one robot: how many episodes reached the target, how fast, and the
 * obedience per phase over all episodes together.
 *
 * @param robot            the robot's name, as the report shows it
 * @param episodes         episodes run
 * @param reached          episodes that reached the target
 * @param meanTimeToReachS mean time to reach over the episodes that reached it; NaN if none did
 * @param medianTimeToReachS median of the same; NaN if none did
 * @param obedience        commands and obeyed per phase, summed over episodes, phases in order of first appearance
 */
public record ScenarioSummary(String robot, int episodes, int reached, double meanTimeToReachS,
        double medianTimeToReachS, List<PhaseObedience> obedience) {

    public ScenarioSummary {
        Objects.requireNonNull(robot, "robot");
        obedience = List.copyOf(obedience);
    }

    /** Sums up a run's episodes. */
    public static ScenarioSummary of(String robot, List<EpisodeResult> results) {
        List<Double> times = new ArrayList<>();
        Map<String, PhaseObedience> phases = new LinkedHashMap<>();
        for (EpisodeResult r : results) {
            if (r.reached()) {
                times.add(r.timeToReachS());
            }
            for (PhaseObedience p : r.obedience()) {
                phases.merge(p.phase(), p, PhaseObedience::plus);
            }
        }
        times.sort(null);
        double mean = times.stream().mapToDouble(Double::doubleValue).average().orElse(Double.NaN);
        double median = times.isEmpty() ? Double.NaN : times.size() % 2 == 1 ? times.get(times.size() / 2)
                : (times.get(times.size() / 2 - 1) + times.get(times.size() / 2)) / 2;
        return new ScenarioSummary(robot, results.size(), times.size(), mean, median, List.copyOf(phases.values()));
    }

    /** The share of episodes that reached the target, 0 … 1; NaN without episodes. */
    public double reachedFraction() {
        return episodes == 0 ? Double.NaN : (double) reached / episodes;
    }
}
