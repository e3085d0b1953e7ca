package org.habla.sim.world;

import java.util.List;
import java.util.Map;

/**
 * How the world's scripted teacher behaves; the {@code "teacher"} object of a world file.
 *
 * <table>
 * <caption>teacher settings</caption>
 * <tr><th>name</th><th>type</th><th>unit</th><th>default</th><th>meaning</th></tr>
 * <tr><td>present</td><td>boolean</td><td></td><td>true</td><td>whether the teacher is there at the start</td></tr>
 * <tr><td>commandEveryS</td><td>number</td><td>s</td><td>3</td><td>sim time between two commands</td></tr>
 * <tr><td>judgeAfterS</td><td>number</td><td>s</td><td>1.5</td><td>how long the robot has to obey before the reward</td></tr>
 * <tr><td>patienceS</td><td>number</td><td>s</td><td>1.5</td><td>how much longer the teacher waits for a robot that has
 * not moved at all yet; it judges the robot's first visible move</td></tr>
 * <tr><td>turnThresholdRad</td><td>number</td><td>rad</td><td>0.35</td><td>|bearing| above which the teacher says left/right</td></tr>
 * <tr><td>minTurnRad</td><td>number</td><td>rad</td><td>0.05</td><td>heading change that counts as having turned</td></tr>
 * <tr><td>minMoveM</td><td>number</td><td>m</td><td>0.02</td><td>displacement that counts as having moved</td></tr>
 * <tr><td>notes</td><td>object</td><td></td><td>C5/E5/G5/C6</td><td>label → note name the Pioneer teacher plays</td></tr>
 * <tr><td>phrases</td><td>object</td><td></td><td>go forward/…</td><td>label → phrase the Aibo teacher says</td></tr>
 * </table>
 */
public record TeacherSettings(boolean present, double commandEveryS, double judgeAfterS, double patienceS, double turnThresholdRad,
                              double minTurnRad, double minMoveM, Map<String, String> notes,
                              Map<String, String> phrases) {

    /** The command labels a teacher gives, in the contract's order. */
    public static final List<String> LABELS = List.of("forward", "left", "right", "back");

    /** The contract's defaults. */
    public static final TeacherSettings DEFAULTS = new TeacherSettings(true, 3.0, 1.5, 1.5, 0.35, 0.05, 0.02,
            Map.of("forward", "C5", "left", "E5", "right", "G5", "back", "C6"),
            Map.of("forward", "go forward", "left", "turn left", "right", "turn right", "back", "go back"));

    public TeacherSettings {
        positive("commandEveryS", commandEveryS);
        positive("judgeAfterS", judgeAfterS);
        if (!(patienceS >= 0) || !Double.isFinite(patienceS)) {
            throw new IllegalArgumentException("teacher.patienceS must be a number of seconds, 0 or more, was " + patienceS);
        }
        positive("turnThresholdRad", turnThresholdRad);
        positive("minTurnRad", minTurnRad);
        positive("minMoveM", minMoveM);
        if (judgeAfterS >= commandEveryS) {
            throw new IllegalArgumentException("judgeAfterS (" + judgeAfterS + ") must be shorter than commandEveryS ("
                    + commandEveryS + "): a command is judged before the next one");
        }
        notes = labelMap("notes", notes);
        phrases = labelMap("phrases", phrases);
    }

    private static void positive(String name, double v) {
        if (!(v > 0) || !Double.isFinite(v)) {
            throw new IllegalArgumentException("teacher." + name + " must be a positive number, was " + v);
        }
    }

    private static Map<String, String> labelMap(String name, Map<String, String> map) {
        Map<String, String> copy = Map.copyOf(map);
        for (String label : LABELS) {
            if (!copy.containsKey(label)) {
                throw new IllegalArgumentException("teacher." + name + " lacks the label '" + label + "'");
            }
        }
        for (String key : copy.keySet()) {
            if (!LABELS.contains(key)) {
                throw new IllegalArgumentException("teacher." + name + " has an unknown label '" + key
                        + "' (labels: " + LABELS + ")");
            }
        }
        return copy;
    }

    /** The same settings with the teacher present or away. */
    public TeacherSettings withPresent(boolean p) {
        return new TeacherSettings(p, commandEveryS, judgeAfterS, patienceS, turnThresholdRad, minTurnRad, minMoveM, notes, phrases);
    }
}
