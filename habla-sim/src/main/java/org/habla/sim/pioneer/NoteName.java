package org.habla.sim.pioneer;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** A musical note name in scientific pitch notation ({@code C5}, {@code F#4}, {@code Bb3}) and its frequency (A4 = 440 Hz). */
record NoteName(String name, double hz) {

    private static final Pattern NOTE = Pattern.compile("([A-Ga-g])([#b]?)(-?\\d)");
    private static final int[] SEMITONES_FROM_C = {9, 11, 0, 2, 4, 5, 7}; // A B C D E F G

    static NoteName parse(String name) {
        Matcher m = NOTE.matcher(name.strip());
        if (!m.matches()) {
            throw new IllegalArgumentException("'" + name + "' is not a note name like C5, F#4 or Bb3");
        }
        int semitone = SEMITONES_FROM_C[Character.toUpperCase(m.group(1).charAt(0)) - 'A'];
        semitone += m.group(2).equals("#") ? 1 : m.group(2).equals("b") ? -1 : 0;
        int octave = Integer.parseInt(m.group(3));
        int midi = 12 * (octave + 1) + semitone;
        return new NoteName(name.strip(), 440.0 * Math.pow(2, (midi - 69) / 12.0));
    }
}
