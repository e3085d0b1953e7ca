package org.habla.sim.scenario;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The plot of distance to the target over time: one line per episode, a dot where an episode reached the
 * target, and a legend saying which did.
 */
final class DistancePlot {

    /** Ten colours that stay apart from each other; episodes beyond ten reuse them. */
    static final List<String> PALETTE = List.of("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
            "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf");
    static final int LEGEND_ROWS = 16;

    private DistancePlot() {
    }

    static String svg(String robot, List<EpisodeResult> episodes) {
        double maxT = 0;
        double maxD = 0;
        for (EpisodeResult e : episodes) {
            for (DistanceSample s : e.distance()) {
                maxT = Math.max(maxT, s.tS());
                maxD = Math.max(maxD, s.distanceM());
            }
        }
        PlotFrame frame = new PlotFrame("Distance to the target over time — " + robot, "time (s)",
                "distance (m)", Ticks.nice(0, maxT, 8), Ticks.nice(0, maxD, 6));
        for (int i = 0; i < episodes.size(); i++) {
            EpisodeResult e = episodes.get(i);
            String colour = PALETTE.get(i % PALETTE.size());
            List<double[]> points = new ArrayList<>();
            for (DistanceSample s : e.distance()) {
                points.add(new double[] {frame.px(s.tS()), frame.py(s.distanceM())});
            }
            String label = "episode " + e.episode() + (e.reached()
                    ? String.format(Locale.ROOT, ": reached in %.1f s", e.timeToReachS()) : ": not reached");
            if (!points.isEmpty()) {
                frame.polyline(points, colour, label);
                if (e.reached()) {
                    double[] end = points.getLast();
                    frame.circle(end[0], end[1], 4, colour, label);
                }
            }
            if (i < LEGEND_ROWS) {
                frame.legend(i, colour, label.replace(": reached in ", " ✓ ").replace(": not reached", " ✗"));
            }
        }
        return frame.render();
    }
}
