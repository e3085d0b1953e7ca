package org.habla.sim.world;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Where everything really is at one instant of sim time; one line of the ground-truth server.
 *
 * @param distanceM surface distance from the robot's edge to the target's edge (≥ 0)
 * @param angleRad  bearing of the target's centre in the robot's frame, + left
 */
public record GroundTruth(double t, Pose2 robot, Target target, double distanceM, double angleRad, boolean stalled,
                          boolean teacherPresent, String lastCommand, Double lastReward, int commands, int plus,
                          int minus, int episode) {

    /** The contract's JSON shape. */
    public ObjectNode toJson() {
        JsonNodeFactory f = JsonNodeFactory.instance;
        ObjectNode o = f.objectNode();
        o.put("t", round(t, 3));
        o.putObject("robot").put("xM", round(robot.xM(), 4)).put("yM", round(robot.yM(), 4))
                .put("thetaRad", round(robot.thetaRad(), 4));
        o.putObject("target").put("xM", target.xM()).put("yM", target.yM()).put("radiusM", target.radiusM());
        o.put("distanceM", round(distanceM, 4));
        o.put("angleRad", round(angleRad, 4));
        o.put("stalled", stalled);
        ObjectNode teacher = o.putObject("teacher");
        teacher.put("present", teacherPresent);
        if (lastCommand == null) {
            teacher.putNull("lastCommand");
        } else {
            teacher.put("lastCommand", lastCommand);
        }
        if (lastReward == null) {
            teacher.putNull("lastReward");
        } else {
            teacher.put("lastReward", lastReward);
        }
        teacher.put("commands", commands);
        teacher.put("plus", plus);
        teacher.put("minus", minus);
        o.put("episode", episode);
        return o;
    }

    private static double round(double v, int digits) {
        double scale = Math.pow(10, digits);
        return Math.round(v * scale) / scale;
    }
}
