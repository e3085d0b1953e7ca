package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A scenario: which robot, its config, its world, and how the paper's experiment runs on it — how many
 * episodes, how long the teacher stays, how long the robot is then left alone, where each episode starts
 * and how close to the object counts as reaching it. Read from JSON ({@code scenarios/pioneer.json} in
 * the simulator's resources, or a file given with {@code --scenario}).
 *
 * @param robot       {@code pioneer}, {@code aibo} or {@code ros2-base} (a simulated ROS 2 base, {@link Ros2Base}):
 *                    which simulator to start
 * @param config      the robot's HABLA config, relative to the HABLA home folder
 * @param world       the world file: a resource under {@code worlds/} or a path
 * @param episodes    how many episodes to run
 * @param teacherS    simulated seconds the teacher stays in each episode
 * @param aloneS      simulated seconds the robot is then left alone (at most; an episode ends when it reaches the object)
 * @param reachM      distance to the object's edge under which it counts as reached
 * @param speed       default time scale
 * @param stepS       simulated seconds the control program waits for an action's effect
 * @param rewardWaitS simulated seconds the control program waits beyond that for the teacher's reward (a spoken
 *                    command is heard later than a note, so its reward comes later too)
 * @param starts      start poses, used in turn
 */
public record ScenarioFile(String robot, String config, String world, int episodes, double teacherS, double aloneS,
        double reachM, double speed, double stepS, double rewardWaitS, List<StartPose> starts) {

    /** The simulated robots a scenario may run on. */
    static final List<String> ROBOTS = List.of("pioneer", "aibo", "ros2-base");

    /** A start pose of the robot in the world frame. */
    public record StartPose(double xM, double yM, double thetaRad) {
    }

    public ScenarioFile {
        if (!ROBOTS.contains(robot)) {
            throw new IllegalArgumentException("robot must be one of " + ROBOTS + ", was '" + robot + "'");
        }
        if (episodes < 1 || teacherS <= 0 || aloneS <= 0 || reachM <= 0 || speed < 1 || stepS <= 0 || rewardWaitS < 0) {
            throw new IllegalArgumentException("episodes ≥ 1, teacherS, aloneS, reachM, stepS > 0 and speed ≥ 1 are required");
        }
        if (starts.isEmpty()) {
            throw new IllegalArgumentException("at least one start pose is required");
        }
        starts = List.copyOf(starts);
    }

    /** The built-in scenario of a robot. */
    public static ScenarioFile builtIn(String robot) throws IOException {
        try (InputStream in = ScenarioFile.class.getResourceAsStream("/scenarios/" + robot + ".json")) {
            if (in == null) {
                throw new IOException("no built-in scenario for '" + robot + "' (" + String.join(", ", ROBOTS) + " exist)");
            }
            return parse(new ObjectMapper().readTree(in));
        }
    }

    public static ScenarioFile read(Path file) throws IOException {
        return parse(new ObjectMapper().readTree(Files.readString(file)));
    }

    static ScenarioFile parse(JsonNode n) throws IOException {
        try {
            List<StartPose> starts = new ArrayList<>();
            for (JsonNode s : n.path("starts")) {
                starts.add(new StartPose(s.path("xM").asDouble(), s.path("yM").asDouble(), s.path("thetaRad").asDouble()));
            }
            return new ScenarioFile(text(n, "robot"), text(n, "config"), text(n, "world"), n.path("episodes").asInt(10),
                    n.path("teacherS").asDouble(90), n.path("aloneS").asDouble(60), n.path("reachM").asDouble(0.3),
                    n.path("speed").asDouble(4), n.path("stepS").asDouble(1.2), n.path("rewardWaitS").asDouble(1.0),
                    starts);
        } catch (IllegalArgumentException e) {
            throw new IOException("scenario: " + e.getMessage(), e);
        }
    }

    private static String text(JsonNode n, String key) {
        if (!n.path(key).isTextual()) {
            throw new IllegalArgumentException("'" + key + "' must be a string");
        }
        return n.path(key).asText();
    }

    public ScenarioFile withEpisodes(int n) {
        return new ScenarioFile(robot, config, world, n, teacherS, aloneS, reachM, speed, stepS, rewardWaitS, starts);
    }
}
