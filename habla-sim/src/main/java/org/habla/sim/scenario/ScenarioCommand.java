package org.habla.sim.scenario;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.habla.command.CommandExtension;
import org.habla.command.ExitCodes;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code habla scenario pioneer|aibo|ros2-base|room}: the paper's experiment on a simulated robot — simulator, daemon
 * and control program as three processes — with a report of every episode.
 */
@Command(name = "scenario", mixinStandardHelpOptions = true,
        description = {"Replay the paper's experiment on a simulated robot (or the intelligent room, 'room'): the simulator, the daemon with the robot's "
                + "config and the control program (examples/mdb/mdb.py) run as separate processes over loopback.",
                "Prints progress and a summary table; writes report.json, report.md and SVG plots to the report folder."})
public final class ScenarioCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "ROBOT", description = "pioneer, aibo, ros2-base (a simulated ROS 2 base; ./habla ros2 setup first) or room")
    private String robot;

    @Option(names = "--scenario", paramLabel = "FILE", description = "A scenario file instead of the robot's built-in one.")
    private Path scenarioFile;

    @Option(names = "--episodes", paramLabel = "N", description = "Episodes to run (default: the scenario's).")
    private Integer episodes;

    @Option(names = "--speed", paramLabel = "S", description = "Time scale: the simulated world runs S times faster (default: the scenario's).")
    private Double speed;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1", description = "Seed of the simulator and the control program (default 1).")
    private long seed;

    @Option(names = "--report", paramLabel = "DIR", description = "Report folder (default reports/ROBOT).")
    private Path report;

    @Option(names = "--port-offset", paramLabel = "N", defaultValue = "0",
            description = "Move every port (simulator, daemon, sockets) by N, to run beside another HABLA on this machine.")
    private int portOffset;

    @Option(names = "--home", paramLabel = "DIR", description = "The HABLA folder holding config/ and examples/ (default: found from the launcher or the working folder).")
    private Path home;

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter out = spec.commandLine().getOut();
        if (robot.equals("room")) {
            return room(out, err);
        }
        ScenarioFile sc;
        try {
            sc = scenarioFile != null ? ScenarioFile.read(scenarioFile) : ScenarioFile.builtIn(robot);
        } catch (IOException e) {
            err.println("habla scenario: " + e.getMessage());
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        if (!sc.robot().equals(robot)) {
            err.println("habla scenario: the scenario is for '" + sc.robot() + "', not '" + robot + "'");
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        Path root = home != null ? home : findHome();
        if (root == null) {
            err.println("habla scenario: cannot find the HABLA folder (with config/ and examples/mdb/); pass --home");
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        double s = speed != null ? speed : sc.speed();
        if (!(s >= 1)) {
            err.println("habla scenario: --speed must be 1 or more");
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        // The processes run in the HABLA folder: a report folder given relative to here is made absolute first.
        Path dir = report != null ? report.toAbsolutePath() : root.resolve("reports").resolve(robot);
        ScenarioRunner.Options opts = new ScenarioRunner.Options(sc, episodes != null ? episodes : sc.episodes(), s, seed,
                dir, portOffset, root);
        List<EpisodeResult> logs;
        try {
            logs = new ScenarioRunner(opts, out).run();
        } catch (IOException e) {
            err.println("habla scenario: " + e.getMessage());
            err.println("logs of the simulator, the daemon and the control program are in " + dir);
            err.flush();
            return ExitCodes.RUNTIME_FAILURE;
        }
        ScenarioReport.write(dir, robot, logs);
        out.println("report: " + dir.resolve("report.md"));
        out.flush();
        return ExitCodes.OK;
    }

    /** The room's scenario: broker, simulated room, daemon and control program; its own report. */
    private int room(PrintWriter out, PrintWriter err) throws Exception {
        RoomScenarioFile sc;
        try {
            sc = scenarioFile != null ? RoomScenarioFile.read(scenarioFile) : RoomScenarioFile.builtIn();
        } catch (IOException e) {
            err.println("habla scenario: " + e.getMessage());
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        Path root = home != null ? home : findHome();
        double s = speed != null ? speed : sc.speed();
        if (root == null || !(s >= 1)) {
            err.println("habla scenario: " + (root == null ? "cannot find the HABLA folder; pass --home"
                    : "--speed must be 1 or more"));
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        // The processes run in the HABLA folder: a report folder given relative to here is made absolute first.
        Path dir = report != null ? report.toAbsolutePath() : root.resolve("reports").resolve(robot);
        RoomScenarioRunner runner = new RoomScenarioRunner(new RoomScenarioRunner.Options(sc,
                episodes != null ? episodes : sc.episodes(), s, seed, dir, portOffset, root), out);
        List<RoomPhase> phases;
        try {
            phases = runner.run();
        } catch (IOException e) {
            err.println("habla scenario: " + e.getMessage());
            err.println("logs of the broker, the simulator, the daemon and the control program are in " + dir);
            err.flush();
            return ExitCodes.RUNTIME_FAILURE;
        }
        RoomReport.write(dir, phases, runner.traces());
        out.println("report: " + dir.resolve("report.md"));
        out.flush();
        return ExitCodes.OK;
    }

    /** The HABLA folder: the launcher's {@code habla.home}, else the working folder or one above it. */
    static Path findHome() {
        String prop = System.getProperty("habla.home");
        if (prop != null) {
            return Path.of(prop).toAbsolutePath();
        }
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isDirectory(p.resolve("config")) && Files.isRegularFile(p.resolve("examples/mdb/mdb.py"))) {
                return p;
            }
        }
        return null;
    }

    /** Registers {@code habla scenario}. */
    public static final class Extension implements CommandExtension {
        @Override
        public String name() {
            return "scenario";
        }

        @Override
        public Object command() {
            return new ScenarioCommand();
        }
    }
}
