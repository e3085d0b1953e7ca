package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The teacher's side of a run, one JSON line per command given and per judgement, written to
 * {@code teacher.jsonl} in the report folder beside the control program's {@code control.jsonl}:
 *
 * <pre>
 *   {"wall": 1764345600.123, "t": 12.4, "episode": 1, "command": "left", "distanceM": 1.42, "angleRad": 0.91}
 *   {"wall": 1764345601.902, "t": 16.0, "episode": 1, "reward": 1.0}
 * </pre>
 *
 * {@code t} is simulated time, {@code wall} the epoch seconds when the line was read (the control program's
 * decision lines carry the same clock), and distance and angle are where the object really was when the
 * teacher spoke. Read together the two files show, step by step, what was said, what was heard and what was
 * done. It watches the ground truth's running counts, which start again at every reset of the robot.
 */
final class TeacherLog implements AutoCloseable {

    static final String FILE = "teacher.jsonl";
    private static final ObjectMapper JSON = new ObjectMapper();

    private final BufferedWriter out;
    private int commands;
    private int plus;
    private int minus;

    TeacherLog(Path reportDir) throws IOException {
        this.out = Files.newBufferedWriter(reportDir.resolve(FILE), StandardCharsets.UTF_8);
    }

    /** Notes what changed in the teacher's counts since the last state line of episode {@code episode}. */
    void observe(JsonNode state, int episode) throws IOException {
        JsonNode teacher = state.path("teacher");
        int c = teacher.path("commands").asInt();
        int p = teacher.path("plus").asInt();
        int m = teacher.path("minus").asInt();
        if (c < commands || p < plus || m < minus) {  // the counts started again (the robot was reset)
            commands = 0;
            plus = 0;
            minus = 0;
        }
        if (c > commands) {
            write(line(state, episode).put("command", teacher.path("lastCommand").asText())
                    .put("distanceM", state.path("distanceM").asDouble()).put("angleRad", state.path("angleRad").asDouble()));
        }
        if (p > plus || m > minus) {
            write(line(state, episode).put("reward", teacher.path("lastReward").asDouble()));
        }
        commands = c;
        plus = p;
        minus = m;
    }

    private static ObjectNode line(JsonNode state, int episode) {
        return JSON.createObjectNode().put("wall", System.currentTimeMillis() / 1000.0)
                .put("t", state.path("t").asDouble()).put("episode", episode);
    }

    private void write(ObjectNode line) throws IOException {
        out.write(JSON.writeValueAsString(line));
        out.write('\n');
        out.flush();
    }

    @Override
    public void close() throws IOException {
        out.close();
    }
}
