package org.habla.sim.scenario;

import java.util.List;
import java.util.Locale;

/**
 * The bar chart of obedience per phase: one bar per phase, its height the share of commands obeyed over all
 * episodes, labelled with the percentage and the counts; a small dot per episode shows the spread.
 */
final class ObediencePlot {

    static final String BAR = "#4c78a8";
    static final String DOT = "#222222";

    private ObediencePlot() {
    }

    static String svg(ScenarioSummary summary, List<EpisodeResult> episodes) {
        PlotFrame frame = new PlotFrame("Obedience per phase — " + summary.robot(), "phase",
                "commands obeyed (%)", null, new Ticks(0, 100, 20));
        List<PhaseObedience> phases = summary.obedience();
        int n = Math.max(1, phases.size());
        double slot = 1.0 / n;
        for (int i = 0; i < phases.size(); i++) {
            PhaseObedience p = phases.get(i);
            double left = frame.px(i * slot + slot * 0.2);
            double right = frame.px(i * slot + slot * 0.8);
            double centre = (left + right) / 2;
            double percent = p.commands() == 0 ? 0 : 100 * p.fraction();
            String label = p.commands() == 0 ? "no commands"
                    : String.format(Locale.ROOT, "%.0f %% (%d of %d)", percent, p.obeyed(), p.commands());
            double top = frame.py(percent);
            frame.rect(left, top, right - left, frame.py(0) - top, BAR, p.phase() + ": " + label);
            frame.text(centre, top - 6, "middle", 11, label, false);
            frame.text(centre, frame.py(0) + 18, "middle", 12, p.phase(), false);
            int k = 0;
            for (EpisodeResult e : episodes) {
                for (PhaseObedience q : e.obedience()) {
                    if (q.phase().equals(p.phase()) && q.commands() > 0) {
                        double x = left + (right - left) * (0.1 + 0.8 * ((k++ * 0.618) % 1.0));
                        frame.circle(x, frame.py(100 * q.fraction()), 2.5, DOT, String.format(Locale.ROOT,
                                "episode %d: %d of %d", e.episode(), q.obeyed(), q.commands()));
                    }
                }
            }
        }
        frame.legend(0, BAR, "all episodes");
        frame.legend(1, DOT, "one episode");
        return frame.render();
    }
}
