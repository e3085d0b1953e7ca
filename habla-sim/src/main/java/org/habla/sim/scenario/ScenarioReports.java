package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** Writes a scenario's report: {@code report.json} with every episode's figures. */
final class ScenarioReports {

    private ScenarioReports() {
    }

    static void write(Path dir, String robot, ScenarioRunner.Options o, List<EpisodeLog> logs) throws IOException {
        ObjectMapper json = new ObjectMapper();
        ObjectNode root = json.createObjectNode();
        root.put("robot", robot);
        root.put("episodes", logs.size());
        root.put("speed", o.speed());
        root.put("seed", o.seed());
        root.put("teacherS", o.scenario().teacherS());
        root.put("aloneS", o.scenario().aloneS());
        root.put("reachM", o.scenario().reachM());
        long reached = logs.stream().filter(EpisodeLog::reached).count();
        root.put("reached", reached);
        root.put("reachedShare", logs.isEmpty() ? 0 : (double) reached / logs.size());
        ArrayNode eps = root.putArray("episodeResults");
        for (EpisodeLog e : logs) {
            ObjectNode n = eps.addObject();
            n.put("episode", e.episode());
            n.putObject("start").put("xM", e.start().xM()).put("yM", e.start().yM()).put("thetaRad", e.start().thetaRad());
            ArrayNode ob = n.putArray("obedienceByThird");
            for (double x : e.obedience()) {
                if (Double.isNaN(x)) {
                    ob.addNull();
                } else {
                    ob.add(x);
                }
            }
            n.put("commands", e.commands());
            n.put("plus", e.plus());
            n.put("minus", e.minus());
            n.put("teacherLeftS", e.teacherLeftS());
            n.put("reached", e.reached());
            if (e.reached()) {
                n.put("reachAfterS", e.reachAfterS());
            } else {
                n.putNull("reachAfterS");
            }
            n.put("finalDistanceM", e.finalDistanceM());
            ArrayNode d = n.putArray("distance");
            for (double[] p : e.distance()) {
                d.addArray().add(Math.round(p[0] * 100) / 100.0).add(Math.round(p[1] * 1000) / 1000.0);
            }
        }
        Files.createDirectories(dir);
        Files.writeString(dir.resolve("report.json"), json.writerWithDefaultPrettyPrinter().writeValueAsString(root));
    }
}
