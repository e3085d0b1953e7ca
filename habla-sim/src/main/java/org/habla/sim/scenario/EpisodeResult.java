package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;

/**
 * What one episode of a scenario came to: how well the robot obeyed in each phase, how far it was from the
 * target over time, and whether and when it reached it.
 *
 * <p>In JSON (what {@link #toJson()} writes and {@link #fromJson(JsonNode)} reads):
 * <pre>
 * {"episode": 1,
 *  "obedience": [{"phase": "teaching", "commands": 30, "obeyed": 24}, ...],
 *  "distance": [[0.0, 2.1], [0.1, 2.1], ...],          [seconds, metres] pairs in time order
 *  "reached": true, "timeToReachS": 21.4}               null when not reached
 * </pre>
 *
 * @param episode      the episode's number, from 1
 * @param obedience    obedience per phase, in the order the phases happened
 * @param distance     distance samples in time order
 * @param reached      whether the robot reached the target
 * @param timeToReachS seconds from the start of the phase that counts (the teacher gone) to reaching the
 *                     target; NaN when not reached
 */
public record EpisodeResult(int episode, List<PhaseObedience> obedience, List<DistanceSample> distance,
        boolean reached, double timeToReachS) {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    public EpisodeResult {
        if (episode < 1) {
            throw new IllegalArgumentException("episodes are numbered from 1, got " + episode);
        }
        obedience = List.copyOf(obedience);
        distance = List.copyOf(distance);
        if (reached != (Double.isFinite(timeToReachS) && timeToReachS >= 0)) {
            throw new IllegalArgumentException("episode " + episode + ": a reached episode needs a time to reach "
                    + ">= 0 s and one not reached needs NaN, got reached=" + reached + ", " + timeToReachS);
        }
        for (int i = 1; i < distance.size(); i++) {
            if (distance.get(i).tS() < distance.get(i - 1).tS()) {
                throw new IllegalArgumentException("episode " + episode + ": distance samples go back in time at "
                        + "index " + i);
            }
        }
        if (obedience.stream().map(PhaseObedience::phase).distinct().count() != obedience.size()) {
            throw new IllegalArgumentException("episode " + episode + ": a phase is listed twice");
        }
    }

    /** An episode in which the robot did not reach the target. */
    public static EpisodeResult notReached(int episode, List<PhaseObedience> obedience, List<DistanceSample> distance) {
        return new EpisodeResult(episode, obedience, distance, false, Double.NaN);
    }

    /** The last distance sampled; NaN without samples. */
    public double finalDistanceM() {
        return distance.isEmpty() ? Double.NaN : distance.getLast().distanceM();
    }

    /** This episode as JSON. */
    public ObjectNode toJson() {
        ObjectNode o = NODES.objectNode().put("episode", episode);
        ArrayNode phases = o.putArray("obedience");
        for (PhaseObedience p : obedience) {
            phases.addObject().put("phase", p.phase()).put("commands", p.commands()).put("obeyed", p.obeyed());
        }
        ArrayNode samples = o.putArray("distance");
        for (DistanceSample s : distance) {
            samples.addArray().add(s.tS()).add(s.distanceM());
        }
        o.put("reached", reached);
        if (reached) {
            o.put("timeToReachS", timeToReachS);
        } else {
            o.putNull("timeToReachS");
        }
        return o;
    }

    /**
     * Reads an episode from JSON.
     *
     * @throws IllegalArgumentException naming the field that is missing or wrong
     */
    public static EpisodeResult fromJson(JsonNode node) {
        if (node == null || !node.isObject()) {
            throw new IllegalArgumentException("an episode is a JSON object");
        }
        int episode = whole(node, "episode");
        List<PhaseObedience> obedience = new ArrayList<>();
        for (JsonNode p : array(node, "obedience")) {
            if (!p.path("phase").isTextual()) {
                throw new IllegalArgumentException("episode " + episode + ": obedience entries need a \"phase\"");
            }
            obedience.add(new PhaseObedience(p.get("phase").asText(), whole(p, "commands"), whole(p, "obeyed")));
        }
        List<DistanceSample> distance = new ArrayList<>();
        for (JsonNode s : array(node, "distance")) {
            if (!s.isArray() || s.size() != 2 || !s.get(0).isNumber() || !s.get(1).isNumber()) {
                throw new IllegalArgumentException("episode " + episode + ": distance samples are [seconds, metres]");
            }
            distance.add(new DistanceSample(s.get(0).asDouble(), s.get(1).asDouble()));
        }
        JsonNode reached = node.get("reached");
        if (reached == null || !reached.isBoolean()) {
            throw new IllegalArgumentException("episode " + episode + ": \"reached\" must be true or false");
        }
        JsonNode time = node.path("timeToReachS");
        double t = time.isNumber() ? time.asDouble() : Double.NaN;
        return new EpisodeResult(episode, obedience, distance, reached.booleanValue(), t);
    }

    private static int whole(JsonNode node, String field) {
        JsonNode v = node.get(field);
        if (v == null || !v.canConvertToInt() || !v.isIntegralNumber()) {
            throw new IllegalArgumentException("\"" + field + "\" must be a whole number, got " + v);
        }
        return v.intValue();
    }

    private static JsonNode array(JsonNode node, String field) {
        JsonNode v = node.get(field);
        if (v == null || !v.isArray()) {
            throw new IllegalArgumentException("\"" + field + "\" must be an array");
        }
        return v;
    }
}
