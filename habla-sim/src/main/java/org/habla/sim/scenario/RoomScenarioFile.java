package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The room's scenario: its config, how many episodes, how long the teacher rewards and how long the room is then
 * left alone, the simulated day, and the control program's pace. Read from {@code scenarios/room.json} in the
 * simulator's resources, or a file given with {@code --scenario}.
 *
 * @param config       the room's HABLA config, relative to the HABLA home folder
 * @param episodes     how many episodes: the teacher rewards, then leaves, each time
 * @param teacherS     simulated seconds the teacher stays in each episode
 * @param aloneS       simulated seconds the room is then left alone
 * @param speed        default time scale
 * @param dayS         the length of a simulated day
 * @param dayPhase     where in the day the run starts (0 sunrise, 0.25 noon, 0.5 sunset, 0.75 midnight)
 * @param stepS        simulated seconds between the control program's decisions
 * @param rewardWaitS  simulated seconds the control program waits for a reward
 * @param absentAfterS simulated seconds without a reward after which the control program acts alone
 */
record RoomScenarioFile(String config, int episodes, double teacherS, double aloneS, double speed, double dayS,
        double dayPhase, double stepS, double rewardWaitS, double absentAfterS) {

    RoomScenarioFile {
        if (episodes < 1 || !(teacherS > 0) || !(aloneS > 0) || !(speed >= 1) || !(dayS >= 10) || !(stepS > 0)
                || !(rewardWaitS >= 0) || !(absentAfterS > 0)) {
            throw new IllegalArgumentException("episodes ≥ 1, teacherS, aloneS, stepS, absentAfterS > 0, dayS ≥ 10 and "
                    + "speed ≥ 1 are required");
        }
    }

    static RoomScenarioFile builtIn() throws IOException {
        try (InputStream in = RoomScenarioFile.class.getResourceAsStream("/scenarios/room.json")) {
            return parse(new ObjectMapper().readTree(in));
        }
    }

    static RoomScenarioFile read(Path file) throws IOException {
        return parse(new ObjectMapper().readTree(Files.readString(file)));
    }

    private static RoomScenarioFile parse(JsonNode n) throws IOException {
        if (!n.path("robot").asText().equals("room")) {
            throw new IOException("the scenario is for '" + n.path("robot").asText() + "', not 'room'");
        }
        try {
            return new RoomScenarioFile(n.path("config").asText("config/room.json"), n.path("episodes").asInt(3),
                    n.path("teacherS").asDouble(300), n.path("aloneS").asDouble(300), n.path("speed").asDouble(10),
                    n.path("dayS").asDouble(300), n.path("dayPhase").asDouble(0.4), n.path("stepS").asDouble(2),
                    n.path("rewardWaitS").asDouble(1.5), n.path("absentAfterS").asDouble(20));
        } catch (IllegalArgumentException e) {
            throw new IOException("the room scenario: " + e.getMessage(), e);
        }
    }
}
