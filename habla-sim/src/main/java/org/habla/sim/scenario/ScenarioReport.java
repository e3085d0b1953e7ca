package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * Writes the report of a scenario run on one robot into a directory:
 *
 * <pre>
 *   report.json     the summary and every episode (see {@link EpisodeResult} for an episode's shape)
 *   report.md       the same for people: summary, obedience table, per-episode table, the plots
 *   distance.svg    distance to the target over time, one line per episode
 *   obedience.svg   obedience per phase, a bar per phase
 * </pre>
 *
 * Existing files of those names are replaced; nothing else in the directory is touched.
 */
public final class ScenarioReport {

    public static final String JSON = "report.json";
    public static final String MARKDOWN = "report.md";
    public static final String DISTANCE_SVG = "distance.svg";
    public static final String OBEDIENCE_SVG = "obedience.svg";

    private static final ObjectMapper MAPPER = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private ScenarioReport() {
    }

    /**
     * Writes the four files for {@code robot}'s episodes into {@code dir} (created if missing).
     *
     * @return the summary the report shows
     */
    public static ScenarioSummary write(Path dir, String robot, List<EpisodeResult> episodes) throws IOException {
        ScenarioSummary summary = ScenarioSummary.of(robot, episodes);
        Files.createDirectories(dir);
        Files.writeString(dir.resolve(JSON), MAPPER.writeValueAsString(json(summary, episodes)) + "\n",
                StandardCharsets.UTF_8);
        Files.writeString(dir.resolve(DISTANCE_SVG), DistancePlot.svg(robot, episodes), StandardCharsets.UTF_8);
        Files.writeString(dir.resolve(OBEDIENCE_SVG), ObediencePlot.svg(summary, episodes), StandardCharsets.UTF_8);
        Files.writeString(dir.resolve(MARKDOWN), markdown(summary, episodes), StandardCharsets.UTF_8);
        return summary;
    }

    /**
     * Reads episodes from a JSON file: an array of episodes, or a {@code report.json} (its
     * {@code "episodeResults"}), so a report can be written again from an earlier one.
     *
     * @throws IllegalArgumentException naming the episode and field that are wrong
     */
    public static List<EpisodeResult> readEpisodes(Path file) throws IOException {
        JsonNode root = MAPPER.readTree(file.toFile());
        JsonNode list = root != null && root.isObject() ? root.get("episodeResults") : root;
        if (list == null || !list.isArray()) {
            throw new IllegalArgumentException(file + ": expected an array of episodes or a report with "
                    + "\"episodeResults\"");
        }
        List<EpisodeResult> episodes = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            try {
                episodes.add(EpisodeResult.fromJson(list.get(i)));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(file + ": episode at index " + i + ": " + e.getMessage(), e);
            }
        }
        return episodes;
    }

    static ObjectNode json(ScenarioSummary s, List<EpisodeResult> episodes) {
        ObjectNode o = MAPPER.createObjectNode().put("robot", s.robot()).put("episodes", s.episodes())
                .put("reached", s.reached());
        number(o, "reachedFraction", s.reachedFraction());
        number(o, "meanTimeToReachS", s.meanTimeToReachS());
        number(o, "medianTimeToReachS", s.medianTimeToReachS());
        ArrayNode phases = o.putArray("obedience");
        for (PhaseObedience p : s.obedience()) {
            ObjectNode n = phases.addObject().put("phase", p.phase()).put("commands", p.commands())
                    .put("obeyed", p.obeyed());
            number(n, "fraction", p.fraction());
        }
        ArrayNode list = o.putArray("episodeResults");
        episodes.forEach(e -> list.add(e.toJson()));
        return o;
    }

    private static void number(ObjectNode o, String field, double value) {
        if (Double.isFinite(value)) {
            o.put(field, value);
        } else {
            o.putNull(field);
        }
    }

    static String markdown(ScenarioSummary s, List<EpisodeResult> episodes) {
        StringBuilder md = new StringBuilder();
        md.append("# Scenario report: ").append(s.robot()).append("\n\n");
        md.append(String.format(Locale.ROOT, "%d of %d episodes reached the target (%s).", s.reached(),
                s.episodes(), percent(s.reachedFraction())));
        if (s.reached() > 0) {
            md.append(String.format(Locale.ROOT, " Time to reach: mean %.1f s, median %.1f s.",
                    s.meanTimeToReachS(), s.medianTimeToReachS()));
        }
        md.append("\n\n## Obedience per phase\n\n| phase | commands | obeyed | obedience |\n| --- | ---: | ---: | ---: |\n");
        for (PhaseObedience p : s.obedience()) {
            md.append(String.format(Locale.ROOT, "| %s | %d | %d | %s |%n", cell(p.phase()), p.commands(),
                    p.obeyed(), percent(p.fraction())));
        }
        md.append("\n![Obedience per phase](").append(OBEDIENCE_SVG).append(")\n\n");
        md.append("## Distance to the target\n\n![Distance to the target over time](").append(DISTANCE_SVG)
                .append(")\n\n");
        md.append("## Episodes\n\n| episode | reached | time to reach (s) | first distance (m) | last distance (m) "
                + "| obedience |\n| ---: | --- | ---: | ---: | ---: | --- |\n");
        for (EpisodeResult e : episodes) {
            String obedience = e.obedience().stream()
                    .map(p -> cell(p.phase()) + " " + p.obeyed() + "/" + p.commands())
                    .collect(Collectors.joining(", "));
            md.append(String.format(Locale.ROOT, "| %d | %s | %s | %s | %s | %s |%n", e.episode(),
                    e.reached() ? "yes" : "no", e.reached() ? String.format(Locale.ROOT, "%.1f", e.timeToReachS()) : "–",
                    metres(e.distance().isEmpty() ? Double.NaN : e.distance().getFirst().distanceM()),
                    metres(e.finalDistanceM()), obedience));
        }
        return md.toString();
    }

    private static String percent(double fraction) {
        return Double.isFinite(fraction) ? String.format(Locale.ROOT, "%.0f %%", 100 * fraction) : "–";
    }

    private static String metres(double m) {
        return Double.isFinite(m) ? String.format(Locale.ROOT, "%.2f", m) : "–";
    }

    /** Text safe inside a Markdown table cell. */
    private static String cell(String s) {
        return s.replace("|", "\\|").replace("\n", " ");
    }
}
