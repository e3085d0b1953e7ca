package org.habla.sim.scenario;

import java.util.List;

/**
 * What one episode of a scenario measured.
 *
 * @param episode      1-based
 * @param start        the robot's start pose
 * @param obedience    per part of the teacher's stay (first, second, last third): the share of the teacher's
 *                     rewards that were pleasure; NaN where the teacher gave none
 * @param commands     commands the teacher gave
 * @param plus         rewards of pleasure given
 * @param minus        rewards of pain given
 * @param distance     (simulated seconds since the episode began, metres to the object's edge), both phases
 * @param teacherLeftS simulated second of the episode at which the teacher left
 * @param reached      whether the robot reached the object after the teacher left
 * @param reachAfterS  simulated seconds from the teacher leaving to reaching the object; NaN if not reached
 * @param finalDistanceM distance to the object when the episode ended
 */
public record EpisodeLog(int episode, ScenarioFile.StartPose start, double[] obedience, int commands, int plus,
        int minus, List<double[]> distance, double teacherLeftS, boolean reached, double reachAfterS,
        double finalDistanceM) {

    /** The share of pleasure rewards over the whole teacher phase; NaN if none were given. */
    public double overallObedience() {
        return plus + minus == 0 ? Double.NaN : (double) plus / (plus + minus);
    }
}
