package org.habla.methods.voice;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;

/**
 * A small deterministic synthesiser that gives a robot a voice without a speech engine: each emotion
 * word has its own short melody (happy rises in a major chord, sad falls slowly in minor, angry buzzes
 * low, excited trills high, neutral is two level beeps) and any other word becomes a chirp that glides
 * between pitches chosen by its vowels, as long as the word. The same text always gives the same
 * samples. A text may also spell tones directly as {@code hz:ms} pairs, e.g. {@code "440:200 660:100"}.
 */
public final class ToneSynth {

    /** A waveform. */
    public enum Wave { SINE, SQUARE }

    /** One tone gliding from {@code fromHz} to {@code toHz}; a frequency of 0 is a rest. */
    public record Tone(double fromHz, double toHz, int ms, Wave wave) {

        public Tone {
            if (!(fromHz >= 0 && toHz >= 0 && fromHz <= 20_000 && toHz <= 20_000) || ms < 0 || ms > 10_000) {
                throw new IllegalArgumentException("a tone needs 0..20000 Hz and 0..10000 ms, was " + fromHz + "-" + toHz
                        + " Hz, " + ms + " ms");
            }
        }

        static Tone of(double hz, int ms) {
            return new Tone(hz, hz, ms, Wave.SINE);
        }
    }

    private static final double C5 = 523.25;
    private static final double E5 = 659.25;
    private static final double G5 = 783.99;
    private static final Map<String, List<Tone>> MELODIES = Map.of(
            "happy", List.of(Tone.of(C5, 120), Tone.of(E5, 120), Tone.of(G5, 200)),
            "excited", List.of(Tone.of(C5 * 2, 70), Tone.of(E5 * 2, 70), Tone.of(G5 * 2, 70), Tone.of(C5 * 4, 70),
                    Tone.of(0, 40), Tone.of(C5 * 2, 70), Tone.of(E5 * 2, 70), Tone.of(G5 * 2, 70), Tone.of(C5 * 4, 140)),
            "sad", List.of(Tone.of(440.0, 300), Tone.of(349.23, 300), new Tone(293.66, 220, 500, Wave.SINE)),
            "angry", List.of(new Tone(110, 110, 150, Wave.SQUARE), Tone.of(0, 50), new Tone(116.54, 116.54, 150, Wave.SQUARE),
                    Tone.of(0, 50), new Tone(110, 98, 300, Wave.SQUARE)),
            "neutral", List.of(Tone.of(440, 150), Tone.of(0, 80), Tone.of(440, 150)));

    private static final Map<Character, Double> VOWEL_HZ = Map.of(
            'a', 440.0, 'e', 493.88, 'i', 587.33, 'o', 392.0, 'u', 349.23, 'y', 523.25);

    /** Milliseconds of fade at each end of a tone, so tones do not click. */
    private static final int FADE_MS = 5;

    private ToneSynth() {
    }

    /** The tones that say {@code text}: a melody per emotion word, a chirp per other word, rests between words. */
    public static List<Tone> tones(String text, int wordGapMs) {
        List<Tone> out = new ArrayList<>();
        String clean = text.trim();
        List<Tone> spelled = spelledTones(clean);
        if (!spelled.isEmpty()) {
            return spelled;
        }
        for (String word : clean.toLowerCase(Locale.ROOT).split("[^\\p{L}\\p{N}]+")) {
            if (word.isEmpty()) {
                continue;
            }
            if (!out.isEmpty()) {
                out.add(Tone.of(0, wordGapMs));
            }
            List<Tone> melody = MELODIES.get(word);
            out.addAll(melody != null ? melody : chirp(word));
        }
        return out;
    }

    /** Whether {@code word} has a melody of its own. */
    public static boolean hasMelody(String word) {
        return MELODIES.containsKey(word.toLowerCase(Locale.ROOT));
    }

    /**
     * A word's chirp: one tone per syllable (a run of vowels with the consonants before it), 60 ms a
     * letter in all (80..400 ms). A syllable's pitch is its first vowel's, moved by up to three
     * semitones either way by the consonants before it, gliding a semitone up or down by the vowel after.
     */
    static List<Tone> chirp(String word) {
        List<Tone> out = new ArrayList<>();
        int total = Math.max(80, Math.min(400, 60 * word.length()));
        List<double[]> syllables = new ArrayList<>();
        int consonants = 0;
        for (int i = 0; i < word.length(); i++) {
            char c = word.charAt(i);
            Double hz = VOWEL_HZ.get(c);
            if (hz == null) {
                consonants += c;
                continue;
            }
            if (i > 0 && VOWEL_HZ.containsKey(word.charAt(i - 1))) {
                continue;
            }
            double start = hz * Math.pow(2, (consonants % 7 - 3) / 12.0);
            double glide = i + 1 < word.length() && VOWEL_HZ.containsKey(word.charAt(i + 1)) ? 1 : -1;
            syllables.add(new double[] {start, start * Math.pow(2, glide / 12.0)});
            consonants = 0;
        }
        if (syllables.isEmpty()) {
            double hz = 330 + 20 * (consonants % 10);
            syllables.add(new double[] {hz, hz});
        }
        int each = total / syllables.size();
        for (double[] s : syllables) {
            out.add(new Tone(s[0], s[1], each, Wave.SINE));
        }
        return out;
    }

    /** Tones spelled as {@code hz:ms} pairs; empty unless the whole text is such pairs. */
    static List<Tone> spelledTones(String text) {
        if (!text.matches("\\d+(\\.\\d+)?:\\d+(\\s+\\d+(\\.\\d+)?:\\d+)*")) {
            return List.of();
        }
        List<Tone> out = new ArrayList<>();
        for (String pair : text.split("\\s+")) {
            String[] p = pair.split(":");
            out.add(Tone.of(Double.parseDouble(p[0]), Integer.parseInt(p[1])));
        }
        return out;
    }

    /** The samples of {@code tones}, in [-amplitude, amplitude], at {@code rateHz}. */
    public static double[] render(List<Tone> tones, int rateHz, double amplitude) {
        long total = 0;
        for (Tone t : tones) {
            total += (long) t.ms() * rateHz / 1000;
        }
        double[] out = new double[(int) Math.min(total, Integer.MAX_VALUE - 8)];
        int at = 0;
        for (Tone t : tones) {
            int n = (int) ((long) t.ms() * rateHz / 1000);
            int fade = Math.min(n / 2, FADE_MS * rateHz / 1000);
            double phase = 0;
            for (int i = 0; i < n && at < out.length; i++, at++) {
                if (t.fromHz() == 0 && t.toHz() == 0) {
                    continue;
                }
                double hz = t.fromHz() + (t.toHz() - t.fromHz()) * i / Math.max(1, n - 1);
                phase += 2 * Math.PI * hz / rateHz;
                double s = Math.sin(phase);
                if (t.wave() == Wave.SQUARE) {
                    s = Math.signum(s) * 0.6;
                }
                double env = Math.min(1, Math.min((i + 1.0) / Math.max(1, fade), (n - i) / (double) Math.max(1, fade)));
                out[at] = amplitude * env * s;
            }
        }
        return out;
    }

    /** Samples as mono 16-bit PCM chunks of at most {@code maxChunkMs} each. */
    public static List<AudioChunk> chunks(double[] samples, int rateHz, int maxChunkMs) {
        AudioFormat format = new AudioFormat(rateHz, 1, 16);
        int per = Math.max(1, (int) ((long) maxChunkMs * rateHz / 1000));
        List<AudioChunk> out = new ArrayList<>();
        for (int start = 0; start < samples.length; start += per) {
            int n = Math.min(per, samples.length - start);
            byte[] pcm = new byte[n * 2];
            for (int i = 0; i < n; i++) {
                long v = Math.round(samples[start + i] * 32767);
                short s = (short) Math.max(Short.MIN_VALUE, Math.min(Short.MAX_VALUE, v));
                pcm[2 * i] = (byte) s;
                pcm[2 * i + 1] = (byte) (s >> 8);
            }
            out.add(AudioChunk.wrap(format, pcm));
        }
        return out;
    }
}
