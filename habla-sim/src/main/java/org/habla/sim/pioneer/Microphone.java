package org.habla.sim.pioneer;

import java.util.Random;
import org.habla.sim.world.SimClock;

/**
 * The laptop microphone on the simulated Pioneer: a continuous 16 kHz, 16-bit mono signal made in sim time —
 * low background noise, and the teacher's notes (0.4 s sine tones with soft edges) when played. Each step's
 * samples go to a {@link PcmServer}, so the stream runs as fast as sim time does.
 */
final class Microphone implements SimClock.Stepper {

    static final int SAMPLE_RATE = 16_000;
    static final double NOTE_S = 0.4;
    /** Tone amplitude, fraction of full scale. */
    static final double NOTE_LEVEL = 0.3;
    /** Background noise standard deviation, fraction of full scale (about −50 dBFS). */
    static final double NOISE_LEVEL = 0.003;
    private static final double EDGE_S = 0.01;

    private final PcmServer out;
    private final Random random;
    private double owedSamples;
    private double toneHz;
    private long toneSample = -1;
    private double phase;

    Microphone(PcmServer out, Random random) {
        this.out = out;
        this.random = random;
    }

    /** Starts a note now (replacing one still sounding). */
    synchronized void play(NoteName note) {
        toneHz = note.hz();
        toneSample = 0;
        phase = 0;
    }

    @Override
    public synchronized void step(double nowS, double dtS) {
        owedSamples += dtS * SAMPLE_RATE;
        int n = (int) owedSamples;
        owedSamples -= n;
        long toneLength = Math.round(NOTE_S * SAMPLE_RATE);
        if (!out.listening()) {
            // Nobody hears it: let a sounding note run its course without making the samples.
            if (toneSample >= 0) {
                toneSample += n;
                if (toneSample >= toneLength) {
                    toneSample = -1;
                }
            }
            return;
        }
        byte[] pcm = new byte[2 * n];
        for (int i = 0; i < n; i++) {
            double s = random.nextGaussian() * NOISE_LEVEL;
            if (toneSample >= 0) {
                double t = toneSample / (double) SAMPLE_RATE;
                double edge = Math.min(1, Math.min(t, NOTE_S - t) / EDGE_S);
                s += NOTE_LEVEL * edge * Math.sin(phase);
                phase += 2 * Math.PI * toneHz / SAMPLE_RATE;
                if (++toneSample >= toneLength) {
                    toneSample = -1;
                }
            }
            int v = (int) Math.round(Math.max(-1, Math.min(1, s)) * Short.MAX_VALUE);
            pcm[2 * i] = (byte) v;
            pcm[2 * i + 1] = (byte) (v >> 8);
        }
        out.send(pcm);
    }
}
