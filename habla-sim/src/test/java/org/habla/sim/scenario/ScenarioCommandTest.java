package org.habla.sim.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * {@code habla scenario} as a user runs it: the simulator, the daemon and the control program start as
 * three processes, an episode runs through the ground truth, and the report is written.
 */
class ScenarioCommandTest {

    private static final Path HOME = Path.of("").toAbsolutePath().getParent();

    @Test
    @Timeout(240)
    void aShortPioneerScenarioRunsThreeProcessesAndWritesItsReport(@TempDir Path dir) throws Exception {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = new CommandLine(new ScenarioCommand());
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        int port = org.habla.sim.PortBlock.freeOffset();
        int code = cli.execute("pioneer", "--scenario", "src/test/resources/scenarios/pioneer-short.json",
                "--home", HOME.toString(), "--report", dir.toString(), "--port-offset", "" + port, "--seed", "3");
        assertThat(code).as("exit code; out:%n%s%nerr:%n%s", out, err).isZero();
        assertThat(out.toString()).contains("episode 1/1").contains("reached after the teacher left:");

        JsonNode report = new ObjectMapper().readTree(Files.readString(dir.resolve("report.json")));
        JsonNode episode = report.path("episodeResults").get(0);
        assertThat(episode.path("episode").asInt()).isEqualTo(1);
        int judged = 0;
        for (JsonNode phase : episode.path("obedience")) {
            judged += phase.path("commands").asInt();
        }
        assertThat(judged).as("the teacher judged the robot's actions").isPositive();
        assertThat(episode.path("distance").size()).as("distance sampled through both phases").isGreaterThan(100);
        assertThat(Files.readString(dir.resolve("report.md"))).contains("pioneer");
        assertThat(Files.readString(dir.resolve("distance.svg"))).contains("<svg").contains("polyline");
        assertThat(dir.resolve("obedience.svg")).exists();
        // The control program really drove: its decision log names actions.
        assertThat(Files.readString(dir.resolve("control.jsonl"))).contains("\"action\"");
    }

    @Test
    @Timeout(240)
    void aShortRos2BaseScenarioRunsTheSimulatedBaseTheBodyTheDaemonAndTheControlProgram(@TempDir Path dir) throws Exception {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = new CommandLine(new ScenarioCommand());
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        int port = org.habla.sim.PortBlock.freeOffset();
        int code = cli.execute("ros2-base", "--scenario", "src/test/resources/scenarios/ros2-base-short.json",
                "--home", HOME.toString(), "--report", dir.toString(), "--port-offset", "" + port, "--seed", "3");
        assertThat(code).as("exit code; out:%n%s%nerr:%n%s", out, err).isZero();
        assertThat(out.toString()).contains("simulated ros2-base started").contains("reached after the teacher left:");
        JsonNode episode = new ObjectMapper().readTree(Files.readString(dir.resolve("report.json")))
                .path("episodeResults").get(0);
        int judged = 0;
        for (JsonNode phase : episode.path("obedience")) {
            judged += phase.path("commands").asInt();
        }
        assertThat(judged).as("the teacher judged the base's moves").isPositive();
        assertThat(Files.readString(dir.resolve("body.log"))).contains("HABLA connected");
        assertThat(Files.readString(dir.resolve("control.jsonl"))).contains("\"action\"");
    }

    @Test
    void anUnknownRobotIsAUsageError() {
        StringWriter err = new StringWriter();
        CommandLine cli = new CommandLine(new ScenarioCommand());
        cli.setErr(new PrintWriter(err, true));
        assertThat(cli.execute("roomba", "--home", HOME.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("no built-in scenario for 'roomba'");
    }
}
