package org.habla.methods.notes;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A note of the equal-tempered scale, by its MIDI number (A4 = 69, C4 = 60), written in scientific
 * pitch notation: a letter, an optional sharp ({@code #}) or flat ({@code b}) and an octave, e.g.
 * {@code C5}, {@code F#4}, {@code Bb3}. Names come out with sharps.
 */
public record Note(int midi) {

    private static final String[] NAMES = {"C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B"};
    private static final Pattern SYNTAX = Pattern.compile("([A-Ga-g])([#b]?)(-?\\d)");
    private static final int[] LETTER_SEMITONES = {9, 11, 0, 2, 4, 5, 7}; // A B C D E F G

    public Note {
        if (midi < 0 || midi > 127) {
            throw new IllegalArgumentException("a note's MIDI number is within 0..127, was " + midi);
        }
    }

    /** The note a name stands for; throws naming the bad name. */
    public static Note parse(String name) {
        Matcher m = SYNTAX.matcher(name == null ? "" : name.trim());
        if (!m.matches()) {
            throw new IllegalArgumentException("'" + name + "' is not a note name like C5, F#4 or Bb3");
        }
        int semitone = LETTER_SEMITONES[Character.toUpperCase(m.group(1).charAt(0)) - 'A'];
        int accidental = m.group(2).equals("#") ? 1 : m.group(2).equals("b") ? -1 : 0;
        int octave = Integer.parseInt(m.group(3));
        return new Note((octave + 1) * 12 + semitone + accidental);
    }

    /** The nearest note to a frequency, given the frequency of A4. */
    public static Note nearest(double hz, double a4Hz) {
        long midi = Math.round(69 + 12 * Math.log(hz / a4Hz) / Math.log(2));
        return new Note((int) Math.max(0, Math.min(127, midi)));
    }

    /** How far {@code hz} is from this note, in cents (hundredths of a semitone). */
    public double centsFrom(double hz, double a4Hz) {
        return 1200 * Math.log(hz / frequency(a4Hz)) / Math.log(2);
    }

    /** The note's frequency, given the frequency of A4. */
    public double frequency(double a4Hz) {
        return a4Hz * Math.pow(2, (midi - 69) / 12.0);
    }

    /** The name in scientific pitch notation, e.g. {@code C5}. */
    public String name() {
        return NAMES[midi % 12] + (midi / 12 - 1);
    }

    @Override
    public String toString() {
        return name();
    }
}
