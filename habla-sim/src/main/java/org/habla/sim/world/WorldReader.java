package org.habla.sim.world;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Reads a world file strictly: an unknown key, a missing field or a number of the wrong kind is an error that
 * names the file and the JSON path, so a typo never silently leaves a default in place.
 *
 * <pre>
 * {"name": "pioneer-room",
 *  "arena": {"walls": [[x1, y1, x2, y2], ...]},
 *  "target": {"xM": 4.5, "yM": 4.5, "radiusM": 0.15, "color": "pink"},
 *  "robot": {"xM": 1.0, "yM": 1.0, "thetaRad": 0.0},
 *  "teacher": {"present": true, "commandEveryS": 3, "judgeAfterS": 1.5, ...}}
 * </pre>
 */
final class WorldReader {

    private static final ObjectMapper JSON = new ObjectMapper().enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION);

    private WorldReader() {
    }

    static World read(InputStream in, String source) throws IOException {
        JsonNode root;
        try {
            root = JSON.readTree(in);
        } catch (JsonProcessingException e) {
            throw new IOException(source + ": not valid JSON: " + e.getOriginalMessage(), e);
        }
        try {
            return world(root);
        } catch (IllegalArgumentException e) {
            throw new IOException(source + ": " + e.getMessage(), e);
        }
    }

    static World world(JsonNode root) {
        object(root, "$", Set.of("name", "description", "arena", "target", "robot", "teacher"));
        String name = text(root, "name", "$");
        JsonNode arena = required(root, "arena", "$");
        object(arena, "$.arena", Set.of("walls"));
        JsonNode wallsNode = required(arena, "walls", "$.arena");
        if (!wallsNode.isArray()) {
            throw new IllegalArgumentException("$.arena.walls must be an array of [x1, y1, x2, y2]");
        }
        List<Segment> walls = new ArrayList<>();
        for (int i = 0; i < wallsNode.size(); i++) {
            JsonNode w = wallsNode.get(i);
            String path = "$.arena.walls[" + i + "]";
            if (!w.isArray() || w.size() != 4) {
                throw new IllegalArgumentException(path + " must be [x1, y1, x2, y2]");
            }
            double[] v = new double[4];
            for (int k = 0; k < 4; k++) {
                if (!w.get(k).isNumber()) {
                    throw new IllegalArgumentException(path + "[" + k + "] must be a number");
                }
                v[k] = w.get(k).doubleValue();
            }
            try {
                walls.add(new Segment(v[0], v[1], v[2], v[3]));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(path + ": " + e.getMessage(), e);
            }
        }
        JsonNode t = required(root, "target", "$");
        object(t, "$.target", Set.of("xM", "yM", "radiusM", "color"));
        Target target = new Target(number(t, "xM", "$.target"), number(t, "yM", "$.target"),
                number(t, "radiusM", "$.target"), t.has("color") ? text(t, "color", "$.target") : "pink");
        JsonNode r = required(root, "robot", "$");
        object(r, "$.robot", Set.of("xM", "yM", "thetaRad"));
        Pose2 start = new Pose2(number(r, "xM", "$.robot"), number(r, "yM", "$.robot"),
                r.has("thetaRad") ? number(r, "thetaRad", "$.robot") : 0);
        TeacherSettings teacher = root.has("teacher") ? teacher(root.get("teacher")) : TeacherSettings.DEFAULTS;
        return new World(name, walls, target, start, teacher);
    }

    private static TeacherSettings teacher(JsonNode t) {
        String p = "$.teacher";
        object(t, p, Set.of("present", "commandEveryS", "judgeAfterS", "patienceS", "turnThresholdRad", "minTurnRad", "minMoveM",
                "notes", "phrases"));
        TeacherSettings d = TeacherSettings.DEFAULTS;
        boolean present = d.present();
        if (t.has("present")) {
            if (!t.get("present").isBoolean()) {
                throw new IllegalArgumentException(p + ".present must be true or false");
            }
            present = t.get("present").booleanValue();
        }
        return new TeacherSettings(present,
                t.has("commandEveryS") ? number(t, "commandEveryS", p) : d.commandEveryS(),
                t.has("judgeAfterS") ? number(t, "judgeAfterS", p) : d.judgeAfterS(),
                t.has("patienceS") ? number(t, "patienceS", p) : d.patienceS(),
                t.has("turnThresholdRad") ? number(t, "turnThresholdRad", p) : d.turnThresholdRad(),
                t.has("minTurnRad") ? number(t, "minTurnRad", p) : d.minTurnRad(),
                t.has("minMoveM") ? number(t, "minMoveM", p) : d.minMoveM(),
                t.has("notes") ? strings(t.get("notes"), p + ".notes") : d.notes(),
                t.has("phrases") ? strings(t.get("phrases"), p + ".phrases") : d.phrases());
    }

    private static Map<String, String> strings(JsonNode node, String path) {
        if (!node.isObject()) {
            throw new IllegalArgumentException(path + " must be an object of label → text");
        }
        Map<String, String> out = new HashMap<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            if (!e.getValue().isTextual()) {
                throw new IllegalArgumentException(path + "." + e.getKey() + " must be a string");
            }
            out.put(e.getKey(), e.getValue().textValue());
        }
        return out;
    }

    private static void object(JsonNode node, String path, Set<String> allowed) {
        if (node == null || !node.isObject()) {
            throw new IllegalArgumentException(path + " must be an object");
        }
        for (Iterator<String> it = node.fieldNames(); it.hasNext(); ) {
            String key = it.next();
            if (!allowed.contains(key)) {
                throw new IllegalArgumentException(path + "." + key + " is not a known key (known: "
                        + allowed.stream().sorted().toList() + ")");
            }
        }
    }

    private static JsonNode required(JsonNode node, String key, String path) {
        JsonNode v = node.get(key);
        if (v == null || v.isNull()) {
            throw new IllegalArgumentException(path + "." + key + " is missing");
        }
        return v;
    }

    private static double number(JsonNode node, String key, String path) {
        JsonNode v = required(node, key, path);
        if (!v.isNumber()) {
            throw new IllegalArgumentException(path + "." + key + " must be a number");
        }
        return v.doubleValue();
    }

    private static String text(JsonNode node, String key, String path) {
        JsonNode v = required(node, key, path);
        if (!v.isTextual()) {
            throw new IllegalArgumentException(path + "." + key + " must be a string");
        }
        return v.textValue();
    }
}
