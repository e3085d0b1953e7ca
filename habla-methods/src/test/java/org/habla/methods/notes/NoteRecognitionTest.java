package org.habla.methods.notes;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.habla.config.ParamsJson;
import org.habla.method.MethodHarness;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.Test;

class NoteRecognitionTest {

    private static final int RATE = 16_000;
    private static final double CHUNK_S = 0.02;
    private static final List<String> TEACHER_NOTES = List.of("C5", "E5", "G5", "C6");

    private static NoteRecognitionParams teacherNotes() {
        return ParamsJson.of(NoteRecognitionParams.class, "{\"notes\": [\"C5\", \"E5\", \"G5\", \"C6\"]}");
    }

    /** A played note: name, start and end in seconds. */
    private record Played(String name, double startS, double endS) {
    }

    /** Streams {@code x} in 20 ms chunks stamped with their end time, as a microphone would deliver them. */
    private static void stream(MethodHarness h, double[] x) {
        int chunk = (int) Math.round(CHUNK_S * RATE);
        for (int start = 0; start < x.length; start += chunk) {
            int end = Math.min(x.length, start + chunk);
            byte[] pcm = new byte[(end - start) * 2];
            for (int i = start; i < end; i++) {
                short s = (short) Math.max(-32768, Math.min(32767, Math.round(x[i] * 32768)));
                pcm[2 * (i - start)] = (byte) s;
                pcm[2 * (i - start) + 1] = (byte) (s >> 8);
            }
            h.push("audio", AudioChunk.wrap(AudioFormat.MONO_16K, pcm), Math.round(end * 1e6 / RATE));
        }
    }

    @Test
    void recognisesAtLeast95PercentOfNoisyDetunedTeacherNotesWithoutFalseNotes() {
        Random r = new Random(20261123);
        double sigma = 0.02;
        List<Played> played = new ArrayList<>();
        double t = 0.5;
        for (int i = 0; i < 240; i++) {
            double dur = 0.3 + 0.3 * r.nextDouble();
            played.add(new Played(TEACHER_NOTES.get(r.nextInt(4)), t, t + dur));
            t += dur + 0.2 + 0.8 * r.nextDouble();
        }
        double[] x = new double[(int) ((t + 0.5) * RATE)];
        for (int i = 0; i < x.length; i++) {
            x[i] = r.nextGaussian() * sigma;
        }
        for (Played p : played) {
            double hz = Note.parse(p.name()).frequency(440) * (1 + (2 * r.nextDouble() - 1) * 0.01);
            double snrDb = 20 * r.nextDouble();
            double amplitude = sigma * Math.sqrt(2) * Math.pow(10, snrDb / 20);
            double phase = 2 * Math.PI * r.nextDouble();
            int from = (int) (p.startS() * RATE);
            int to = (int) (p.endS() * RATE);
            for (int i = from; i < to; i++) {
                double ramp = Math.min(1, Math.min(i - from, to - i) / (0.005 * RATE));
                x[i] += ramp * amplitude * Math.sin(2 * Math.PI * hz * (i - from) / RATE + phase);
            }
        }
        MethodHarness h = MethodHarness.started("notes", new NoteRecognition(teacherNotes()));
        long t0 = System.nanoTime();
        stream(h, x);
        double ms = (System.nanoTime() - t0) / 1e6;
        System.out.printf("note-recognition: %.0f s of audio analysed in %.0f ms (%.0f times real time)%n",
                x.length / (double) RATE, ms, x.length / (double) RATE * 1000 / ms);

        int[] heard = new int[played.size()];
        int correct = 0;
        int falseNotes = 0;
        for (Sample s : h.samples("note")) {
            double at = s.sourceMicros() / 1e6;
            String name = ((TextValue) s.payload()).text();
            int match = -1;
            for (int i = 0; i < played.size(); i++) {
                if (at >= played.get(i).startS() && at <= played.get(i).endS() + 0.1) {
                    match = i;
                }
            }
            if (match < 0 || !played.get(match).name().equals(name) || heard[match]++ > 0) {
                falseNotes++;
            }
        }
        for (int count : heard) {
            correct += count == 1 ? 1 : 0;
        }
        double rate = 100.0 * correct / played.size();
        System.out.printf("note-recognition: %d of %d notes correct (%.1f%%), %d false notes (0-20 dB SNR, ±1%% "
                + "detuning, 0.3-0.6 s)%n", correct, played.size(), rate, falseNotes);
        assertThat(played).hasSizeGreaterThanOrEqualTo(200);
        assertThat(rate).isGreaterThanOrEqualTo(95);
        assertThat(falseNotes).isZero();
    }

    @Test
    void pureNoiseOfAnyLevelGivesNoNote() {
        Random r = new Random(77);
        int falseNotes = 0;
        double seconds = 0;
        for (NoteRecognitionParams params : List.of(teacherNotes(), NoteRecognitionParams.defaults())) {
            for (double sigma : new double[] {0.0005, 0.02, 0.3}) {
                MethodHarness h = MethodHarness.started("notes", new NoteRecognition(params));
                double[] x = new double[15 * RATE];
                double brown = 0;
                for (int i = 0; i < x.length; i++) {
                    // white noise for the first half, then brown (low-heavy) noise
                    brown = 0.98 * brown + r.nextGaussian() * sigma * 0.2;
                    x[i] = i < x.length / 2 ? r.nextGaussian() * sigma : brown;
                }
                stream(h, x);
                falseNotes += h.values("note").size();
                seconds += 15;
            }
        }
        System.out.printf("note-recognition: %d false notes in %.0f s of white and brown noise%n", falseNotes, seconds);
        assertThat(falseNotes).isZero();
    }

    @Test
    void aSustainedNoteIsReportedOnceAndOnlyAllowedNotesAreReported() {
        MethodHarness h = MethodHarness.started("notes", new NoteRecognition(teacherNotes()));
        double[] x = new double[3 * RATE];
        for (int i = 0; i < RATE * 2; i++) {
            x[i] = 0.3 * Math.sin(2 * Math.PI * 659.25 * i / RATE);
        }
        for (int i = RATE * 2; i < x.length; i++) {
            x[i] = 0.3 * Math.sin(2 * Math.PI * 440 * i / RATE);   // A4: not a teacher's note
        }
        stream(h, x);
        assertThat(h.values("note")).containsExactly(new TextValue("E5"));

        MethodHarness any = MethodHarness.started("notes", new NoteRecognition(NoteRecognitionParams.defaults()));
        stream(any, x);
        assertThat(any.values("note")).containsExactly(new TextValue("E5"), new TextValue("A4"));
    }

    @Test
    void aDifferentTuningReferenceShiftsTheNames() {
        NoteRecognitionParams baroque = ParamsJson.of(NoteRecognitionParams.class, "{\"notes\": [], \"referenceA4Hz\": 415.0}");
        MethodHarness h = MethodHarness.started("notes", new NoteRecognition(baroque));
        double[] x = new double[RATE];
        for (int i = 0; i < x.length; i++) {
            x[i] = 0.3 * Math.sin(2 * Math.PI * 415 * i / RATE);
        }
        stream(h, x);
        assertThat(h.values("note")).containsExactly(new TextValue("A4"));
    }
}
