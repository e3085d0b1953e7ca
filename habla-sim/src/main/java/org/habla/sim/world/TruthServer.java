package org.habla.sim.world;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;

/**
 * The ground-truth server: what tests, scenarios and curious users see of the simulated world, one JSON object per
 * line over TCP on loopback. Every {@value #PERIOD_S} s of sim time it sends where the robot and the target are,
 * the robot's distance and bearing to the target, whether it is stalled, what the teacher last did, and the
 * episode number:
 *
 * <pre>
 * {"t":12.3,"robot":{"xM":1.0,"yM":1.2,"thetaRad":0.1},"target":{"xM":4.5,"yM":4.5,"radiusM":0.15},
 *  "distanceM":4.2,"angleRad":0.6,"stalled":false,
 *  "teacher":{"present":true,"lastCommand":"left","lastReward":1.0},"episode":0}
 * </pre>
 *
 * A client may write operations, one JSON object per line, each answered {@code {"ok":true}} or
 * {@code {"error":"..."}}:
 * <ul>
 * <li>{@code {"op":"reset","robot":{"xM","yM","thetaRad"},"target":{"xM","yM","radiusM"}}} — a new episode
 *     (both parts optional: the world's start pose, the target where it is);</li>
 * <li>{@code {"op":"teacher","present":true|false}};</li>
 * <li>{@code {"op":"say","label":"forward"}} or {@code {"op":"note","label":"left"}} — the teacher gives that
 *     command now (and judges it);</li>
 * <li>{@code {"op":"reward","value":1}} — the teacher gives that reward now;</li>
 * <li>{@code {"op":"touch","sensor":"head"|"back"}} — touches the robot (the Aibo).</li>
 * </ul>
 */
public final class TruthServer implements SimClock.Stepper, AutoCloseable {

    /** Sim seconds between two ground-truth lines. */
    public static final double PERIOD_S = 0.1;
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String OK = "{\"ok\":true}";

    private final Scene scene;
    private final LineServer server;
    private double nextS;

    /** Listens on 127.0.0.1:{@code port} (0: any free port). Add it to the clock to start the broadcast. */
    public TruthServer(Scene scene, int port) throws IOException {
        this.scene = scene;
        this.server = new LineServer("ground-truth", port, this::handle);
    }

    public int port() {
        return server.port();
    }

    @Override
    public void step(double nowS, double dtS) {
        if (nowS + 1e-9 >= nextS) {
            nextS = nowS + PERIOD_S;
            if (server.clientCount() > 0) {
                server.broadcast(scene.truthJson().toString());
            }
        }
    }

    @Override
    public void close() {
        server.close();
    }

    /** Carries out one operation line and returns the reply line. */
    String handle(String line) {
        JsonNode op;
        try {
            op = JSON.readTree(line);
        } catch (JsonProcessingException e) {
            return error("not a JSON object: " + e.getOriginalMessage());
        }
        if (op == null || !op.isObject()) {
            return error("an operation must be a JSON object with an \"op\"");
        }
        String name = op.path("op").asText("");
        try {
            switch (name) {
                case "reset" -> scene.reset(op.has("robot") ? pose(op.get("robot")) : null,
                        op.has("target") ? target(op.get("target")) : null);
                case "teacher" -> {
                    JsonNode present = op.get("present");
                    if (present == null || !present.isBoolean()) {
                        return error("teacher needs \"present\": true or false");
                    }
                    scene.teacher().setPresent(present.booleanValue());
                }
                case "say", "note" -> scene.teacher().commandNow(op.path("label").asText(""), scene.body().pose());
                case "reward" -> {
                    JsonNode value = op.get("value");
                    if (value == null || !value.isNumber()) {
                        return error("reward needs a numeric \"value\" in [-1, 1]");
                    }
                    scene.teacher().rewardNow(value.doubleValue());
                }
                case "touch" -> scene.touch(op.path("sensor").asText(""));
                default -> {
                    return error("unknown op '" + name + "' (ops: reset, teacher, say, note, reward, touch)");
                }
            }
        } catch (IllegalArgumentException e) {
            return error(e.getMessage());
        }
        return OK;
    }

    private Pose2 pose(JsonNode node) {
        if (!node.isObject()) {
            throw new IllegalArgumentException("robot must be an object {\"xM\",\"yM\",\"thetaRad\"}");
        }
        Pose2 start = scene.world().robotStart();
        return new Pose2(number(node, "xM", start.xM()), number(node, "yM", start.yM()),
                number(node, "thetaRad", start.thetaRad()));
    }

    private Target target(JsonNode node) {
        if (!node.isObject()) {
            throw new IllegalArgumentException("target must be an object {\"xM\",\"yM\",\"radiusM\"}");
        }
        Target now = scene.target();
        return new Target(number(node, "xM", now.xM()), number(node, "yM", now.yM()),
                number(node, "radiusM", now.radiusM()), now.color());
    }

    private static double number(JsonNode node, String key, double fallback) {
        JsonNode v = node.get(key);
        if (v == null) {
            return fallback;
        }
        if (!v.isNumber()) {
            throw new IllegalArgumentException(key + " must be a number");
        }
        return v.doubleValue();
    }

    private static String error(String message) {
        return JSON.createObjectNode().put("error", message).toString();
    }
}
