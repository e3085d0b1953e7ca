package org.habla.sim.scenario;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

class ScenarioReportTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    static List<DistanceSample> approach(double fromM, double speedMps, double untilS) {
        List<DistanceSample> samples = new ArrayList<>();
        for (double t = 0; t <= untilS + 1e-9; t += 0.5) {
            samples.add(new DistanceSample(t, Math.max(0, fromM - speedMps * t)));
        }
        return samples;
    }

    static List<EpisodeResult> threeEpisodes() {
        return List.of(
                new EpisodeResult(1, List.of(new PhaseObedience("teaching", 30, 24), new PhaseObedience("alone", 0, 0)),
                        approach(2.0, 0.1, 20), true, 20.0),
                new EpisodeResult(2, List.of(new PhaseObedience("teaching", 30, 18)), approach(1.5, 0.1, 15), true, 12.0),
                EpisodeResult.notReached(3, List.of(new PhaseObedience("teaching", 20, 8)), approach(2.5, 0.02, 30)));
    }

    static Document svg(Path file) throws Exception {
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        f.setNamespaceAware(true);
        return f.newDocumentBuilder().parse(file.toFile());
    }

    @Test
    void theReportSumsUpReachingAndObedienceInJson(@TempDir Path dir) throws Exception {
        ScenarioSummary summary = ScenarioReport.write(dir, "pioneer", threeEpisodes());

        assertThat(summary.reached()).isEqualTo(2);
        JsonNode report = JSON.readTree(dir.resolve(ScenarioReport.JSON).toFile());
        assertThat(report.get("robot").asText()).isEqualTo("pioneer");
        assertThat(report.get("episodes").asInt()).isEqualTo(3);
        assertThat(report.get("reached").asInt()).isEqualTo(2);
        assertThat(report.get("reachedFraction").asDouble()).isCloseTo(2.0 / 3, within(1e-9));
        assertThat(report.get("meanTimeToReachS").asDouble()).isCloseTo(16.0, within(1e-9));
        assertThat(report.get("medianTimeToReachS").asDouble()).isCloseTo(16.0, within(1e-9));
        JsonNode teaching = report.get("obedience").get(0);
        assertThat(teaching.get("phase").asText()).isEqualTo("teaching");
        assertThat(teaching.get("commands").asInt()).isEqualTo(80);
        assertThat(teaching.get("obeyed").asInt()).isEqualTo(50);
        assertThat(report.get("obedience").get(1).get("fraction").isNull()).isTrue();
        assertThat(report.get("episodeResults")).hasSize(3);
        assertThat(EpisodeResult.fromJson(report.get("episodeResults").get(2))).isEqualTo(threeEpisodes().get(2));
    }

    @Test
    void theMarkdownReportTablesEveryEpisodeAndShowsThePlots(@TempDir Path dir) throws Exception {
        ScenarioReport.write(dir, "aibo", threeEpisodes());

        String md = Files.readString(dir.resolve(ScenarioReport.MARKDOWN));
        assertThat(md).startsWith("# Scenario report: aibo")
                .contains("2 of 3 episodes reached the target (67 %). Time to reach: mean 16.0 s, median 16.0 s.")
                .contains("| teaching | 80 | 50 | 63 % |")
                .contains("| 1 | yes | 20.0 | 2.00 | 0.00 | teaching 24/30, alone 0/0 |")
                .contains("| 3 | no | – | 2.50 | 1.90 | teaching 8/20 |")
                .contains("](obedience.svg)").contains("](distance.svg)");
    }

    @Test
    void theDistancePlotDrawsOneLineThroughEverySamplePerEpisode(@TempDir Path dir) throws Exception {
        List<EpisodeResult> episodes = threeEpisodes();
        ScenarioReport.write(dir, "pioneer", episodes);

        Document doc = svg(dir.resolve(ScenarioReport.DISTANCE_SVG));
        NodeList lines = doc.getElementsByTagNameNS("http://www.w3.org/2000/svg", "polyline");
        assertThat(lines.getLength()).isEqualTo(3);
        for (int i = 0; i < 3; i++) {
            String[] points = ((Element) lines.item(i)).getAttribute("points").split(" ");
            assertThat(points).hasSize(episodes.get(i).distance().size());
            double firstY = Double.parseDouble(points[0].split(",")[1]);
            double lastY = Double.parseDouble(points[points.length - 1].split(",")[1]);
            assertThat(lastY).as("distance falls, so the line goes down the page: y grows").isGreaterThan(firstY);
        }
        assertThat(doc.getElementsByTagNameNS("http://www.w3.org/2000/svg", "circle").getLength())
                .as("a dot per reached episode").isEqualTo(2);
        assertThat(Files.readString(dir.resolve(ScenarioReport.DISTANCE_SVG)))
                .contains("episode 3: not reached").contains("episode 1: reached in 20.0 s");
    }

    @Test
    void theObedienceBarsAreAsTallAsTheShareObeyed(@TempDir Path dir) throws Exception {
        List<EpisodeResult> episodes = List.of(
                new EpisodeResult(1, List.of(new PhaseObedience("start", 10, 2), new PhaseObedience("end", 10, 8)),
                        approach(1, 0.1, 10), true, 10.0));
        ScenarioReport.write(dir, "pioneer", episodes);

        Document doc = svg(dir.resolve(ScenarioReport.OBEDIENCE_SVG));
        NodeList rects = doc.getElementsByTagNameNS("http://www.w3.org/2000/svg", "rect");
        List<Double> bars = new ArrayList<>();
        for (int i = 0; i < rects.getLength(); i++) {
            Element r = (Element) rects.item(i);
            if (r.getAttribute("fill").equals(ObediencePlot.BAR)
                    && r.getElementsByTagNameNS("http://www.w3.org/2000/svg", "title").getLength() == 1) {
                bars.add(Double.parseDouble(r.getAttribute("height")));
            }
        }
        assertThat(bars).hasSize(2);
        assertThat(bars.get(1) / bars.get(0)).isCloseTo(4.0, within(0.05));
        assertThat(bars.get(1)).isCloseTo(0.8 * PlotFrame.plotHeight(), within(0.2));
        assertThat(Files.readString(dir.resolve(ScenarioReport.OBEDIENCE_SVG))).contains("80 % (8 of 10)")
                .contains(">start<").contains(">end<");
    }

    @Test
    void episodesReadBackFromAReportOrAnArrayAndBadOnesAreNamed(@TempDir Path dir) throws Exception {
        ScenarioReport.write(dir, "pioneer", threeEpisodes());
        assertThat(ScenarioReport.readEpisodes(dir.resolve(ScenarioReport.JSON))).isEqualTo(threeEpisodes());

        Path array = dir.resolve("episodes.json");
        Files.writeString(array, "[" + threeEpisodes().get(0).toJson() + ", {\"episode\": 2}]");
        assertThatThrownBy(() -> ScenarioReport.readEpisodes(array))
                .hasMessageContaining("episode at index 1").hasMessageContaining("\"obedience\" must be an array");
    }

    @Test
    void aReportWithoutReachedEpisodesOrSamplesStillWrites(@TempDir Path dir) throws Exception {
        ScenarioReport.write(dir.resolve("nested"), "rover & <co>",
                List.of(EpisodeResult.notReached(1, List.of(), List.of())));

        JsonNode report = JSON.readTree(dir.resolve("nested").resolve(ScenarioReport.JSON).toFile());
        assertThat(report.get("meanTimeToReachS").isNull()).isTrue();
        assertThat(svg(dir.resolve("nested").resolve(ScenarioReport.DISTANCE_SVG))).isNotNull();
        assertThat(Files.readString(dir.resolve("nested").resolve(ScenarioReport.OBEDIENCE_SVG)))
                .contains("rover &amp; &lt;co&gt;");
    }
}
