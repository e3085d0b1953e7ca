package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Writes the report of a room scenario run into a directory, in the manner of the robots' reports:
 *
 * <pre>
 *   report.json     every phase of every episode (see {@link RoomPhase})
 *   report.md       the same for people: the phases over all episodes, each episode, the plots
 *   decisions.svg   switches right per phase, a bar per phase and a dot per episode
 *   energy.svg      the lamps' energy over each episode, against lighting just the needed zone and every lamp
 * </pre>
 */
final class RoomReport {

    static final String DECISIONS_SVG = "decisions.svg";
    static final String ENERGY_SVG = "energy.svg";
    private static final ObjectMapper MAPPER = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private RoomReport() {
    }

    static void write(Path dir, List<RoomPhase> phases, List<RoomScenarioRunner.Trace> traces) throws IOException {
        Files.createDirectories(dir);
        List<RoomPhase> totals = totals(phases);
        ObjectNode root = MAPPER.createObjectNode().put("robot", "room");
        ArrayNode t = root.putArray("phases");
        totals.forEach(p -> t.add(p.toJson().without("episode")));
        ArrayNode all = root.putArray("episodePhases");
        phases.forEach(p -> all.add(p.toJson()));
        Files.writeString(dir.resolve(ScenarioReport.JSON), MAPPER.writeValueAsString(root) + "\n", StandardCharsets.UTF_8);
        Files.writeString(dir.resolve(DECISIONS_SVG), decisions(totals, phases), StandardCharsets.UTF_8);
        Files.writeString(dir.resolve(ENERGY_SVG), energy(traces), StandardCharsets.UTF_8);
        Files.writeString(dir.resolve(ScenarioReport.MARKDOWN), markdown(totals, phases), StandardCharsets.UTF_8);
    }

    /** Every phase summed over the episodes, in the order they came. */
    static List<RoomPhase> totals(List<RoomPhase> phases) {
        Map<String, RoomPhase> sum = new LinkedHashMap<>();
        for (RoomPhase p : phases) {
            sum.merge(p.phase(), p, (a, b) -> new RoomPhase(0, a.phase(), a.seconds() + b.seconds(),
                    a.switches() + b.switches(), a.right() + b.right(), a.wantedS() + b.wantedS(),
                    a.servedS() + b.servedS(), a.energyWh() + b.energyWh(), a.oracleWh() + b.oracleWh(),
                    a.allOnWh() + b.allOnWh()));
        }
        return new ArrayList<>(sum.values());
    }

    private static String decisions(List<RoomPhase> totals, List<RoomPhase> phases) {
        PlotFrame frame = new PlotFrame("Lamp switches right per phase — room", "phase", "switches right (%)", null,
                new Ticks(0, 100, 20));
        double slot = 1.0 / Math.max(1, totals.size());
        for (int i = 0; i < totals.size(); i++) {
            RoomPhase p = totals.get(i);
            double left = frame.px(i * slot + slot * 0.2);
            double right = frame.px(i * slot + slot * 0.8);
            double percent = p.switches() == 0 ? 0 : 100 * p.rightFraction();
            String label = p.switches() == 0 ? "no switches"
                    : String.format(Locale.ROOT, "%.0f %% (%d of %d)", percent, p.right(), p.switches());
            double top = frame.py(percent);
            frame.rect(left, top, right - left, frame.py(0) - top, ObediencePlot.BAR, p.phase() + ": " + label);
            frame.text((left + right) / 2, top - 6, "middle", 11, label, false);
            frame.text((left + right) / 2, frame.py(0) + 18, "middle", 12, p.phase(), false);
            int k = 0;
            for (RoomPhase q : phases) {
                if (q.phase().equals(p.phase()) && q.switches() > 0) {
                    double x = left + (right - left) * (0.1 + 0.8 * ((k++ * 0.618) % 1.0));
                    frame.circle(x, frame.py(100 * q.rightFraction()), 2.5, ObediencePlot.DOT, String.format(
                            Locale.ROOT, "episode %d: %d of %d", q.episode(), q.right(), q.switches()));
                }
            }
        }
        frame.legend(0, ObediencePlot.BAR, "all episodes");
        frame.legend(1, ObediencePlot.DOT, "one episode");
        return frame.render();
    }

    private static String energy(List<RoomScenarioRunner.Trace> traces) {
        double maxT = 1;
        double maxE = 0.01;
        for (RoomScenarioRunner.Trace t : traces) {
            for (double[] p : t.points()) {
                maxT = Math.max(maxT, p[0]);
                maxE = Math.max(maxE, p[3]);
            }
        }
        PlotFrame frame = new PlotFrame("Lamp energy over an episode — room", "time (s)", "energy (Wh)",
                Ticks.nice(0, maxT, 8), Ticks.nice(0, maxE, 6));
        int row = 0;
        for (int i = 0; i < traces.size(); i++) {
            RoomScenarioRunner.Trace t = traces.get(i);
            String colour = DistancePlot.PALETTE.get(i % DistancePlot.PALETTE.size());
            frame.polyline(column(frame, t, 1), colour, "episode " + t.episode() + ": the lamps");
            frame.legend(row++, colour, "episode " + t.episode());
        }
        if (!traces.isEmpty()) {
            RoomScenarioRunner.Trace first = traces.getFirst();
            frame.polyline(column(frame, first, 2), "#999999", "just the zone that needs light (episode 1)");
            frame.polyline(column(frame, first, 3), "#cccccc", "every lamp on");
            frame.legend(row++, "#999999", "needed zone only");
            frame.legend(row++, "#cccccc", "every lamp on");
            double x = frame.px(first.teacherLeftS());
            frame.line(x, PlotFrame.TOP, x, PlotFrame.TOP + PlotFrame.plotHeight(), PlotFrame.AXIS, 1);
            frame.text(x + 4, PlotFrame.TOP + 12, "start", 11, "the teacher leaves", false);
        }
        return frame.render();
    }

    private static List<double[]> column(PlotFrame frame, RoomScenarioRunner.Trace t, int column) {
        List<double[]> pts = new ArrayList<>();
        for (double[] p : t.points()) {
            pts.add(new double[] {frame.px(p[0]), frame.py(p[column])});
        }
        return pts;
    }

    private static String markdown(List<RoomPhase> totals, List<RoomPhase> phases) {
        StringBuilder b = new StringBuilder("# Scenario report: room\n\n");
        b.append("A teacher rewards the control program's lamp switches with a button (once: right, twice: wrong), ")
                .append("then leaves. A switch is right when it lights the zone the person is in while daylight leaves ")
                .append("it dark, or darkens any other zone. Measured on the simulator's ground truth.\n\n");
        b.append("| phase | switches right | light when needed | energy | needed zone only | every lamp on | waste |\n");
        b.append("| --- | --- | --- | --- | --- | --- | --- |\n");
        for (RoomPhase p : totals) {
            row(b, p.phase(), p);
        }
        b.append("\nWaste is the energy used beyond lighting just the needed zone, as a share of what leaving every lamp ")
                .append("on would have used beyond it (0 % is perfect, 100 % is as bad as every lamp on).\n\n");
        b.append("## Episodes\n\n| episode | phase | switches right | light when needed | energy | needed zone only | every lamp on | waste |\n");
        b.append("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
        for (RoomPhase p : phases) {
            b.append("| ").append(p.episode());
            row(b, p.phase(), p);
        }
        b.append("\n## Plots\n\n![switches right per phase](").append(DECISIONS_SVG).append(")\n\n![energy](")
                .append(ENERGY_SVG).append(")\n");
        return b.toString();
    }

    private static void row(StringBuilder b, String phase, RoomPhase p) {
        b.append("| ").append(phase).append(" | ")
                .append(p.switches() == 0 ? "-" : p.right() + "/" + p.switches() + " (" + ScenarioRunner.pct(p.rightFraction()) + ")")
                .append(" | ").append(ScenarioRunner.pct(p.servedFraction()))
                .append(String.format(Locale.ROOT, " | %.2f Wh | %.2f Wh | %.2f Wh | ", p.energyWh(), p.oracleWh(),
                        p.allOnWh()))
                .append(ScenarioRunner.pct(p.wasteFraction())).append(" |\n");
    }
}
