package org.habla.sim.pioneer;

import java.util.HashMap;
import java.util.Map;
import org.habla.sim.world.LineServer;
import org.habla.sim.world.TeacherSettings;
import org.habla.sim.world.TeacherVoice;

/**
 * How the teacher reaches the Pioneer, as in the paper: a command is a musical note played near the laptop's
 * microphone (the world file maps each label to a note), a reward is a line typed on the keyboard — {@code +1}
 * for pleasure, {@code -1} for pain.
 */
final class PioneerTeacherVoice implements TeacherVoice {

    private final Microphone microphone;
    private final LineServer keyboard;
    private final Map<String, NoteName> notes = new HashMap<>();

    PioneerTeacherVoice(TeacherSettings settings, Microphone microphone, LineServer keyboard) {
        this.microphone = microphone;
        this.keyboard = keyboard;
        settings.notes().forEach((label, note) -> notes.put(label, NoteName.parse(note)));
    }

    @Override
    public double giveCommand(String label) {
        NoteName note = notes.get(label);
        if (note == null) {
            throw new IllegalArgumentException("no note for the command '" + label + "'");
        }
        microphone.play(note);
        return Microphone.NOTE_S;
    }

    @Override
    public void giveReward(double value) {
        keyboard.broadcast(keyLine(value));
    }

    /** The line the teacher types for a reward: {@code +1}, {@code -1}, {@code +0.5}. */
    static String keyLine(double value) {
        String magnitude = value == Math.rint(value) ? String.valueOf((long) Math.abs(value))
                : String.valueOf(Math.abs(value));
        return (value < 0 ? "-" : "+") + magnitude;
    }
}
