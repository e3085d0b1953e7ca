package org.habla.sim.aibo;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.SplittableRandom;

/**
 * What the Aibo's two microphones hear: a timeline of sounds (the teacher's utterances) played one
 * after the other, over low noise. Positions are sample indices at 16 kHz of simulated time since
 * boot, so the sounds keep their place in time whether or not a client is listening.
 */
public final class Microphone {

    public static final int RATE_HZ = 16_000;
    /** The room's noise, in 16-bit sample units (about -55 dB full scale). */
    static final double NOISE_RMS = 60;
    /** How long after its end a sound is kept for a client still behind it: ten seconds. */
    private static final long KEPT_SAMPLES = 10L * RATE_HZ;

    private record Sound(long start, short[] pcm) {
        long end() {
            return start + pcm.length;
        }
    }

    private final Deque<Sound> sounds = new ArrayDeque<>();
    private final SplittableRandom random;

    public Microphone(long seed) {
        this.random = new SplittableRandom(seed);
    }

    /**
     * Queues a mono 16 kHz sound to be heard from {@code nowSample}, or right after the sounds already
     * queued. Returns the sample at which it starts.
     */
    public synchronized long play(short[] mono, long nowSample) {
        // a sound over for a while is forgotten; one just over may still be owed to a client a little behind
        while (!sounds.isEmpty() && sounds.peekFirst().end() <= nowSample - KEPT_SAMPLES) {
            sounds.removeFirst();
        }
        long start = sounds.isEmpty() ? nowSample : Math.max(nowSample, sounds.peekLast().end());
        sounds.addLast(new Sound(start, mono.clone()));
        return start;
    }

    /** {@code frames} stereo frames from {@code fromSample}, interleaved left, right. */
    synchronized short[] stereo(long fromSample, int frames) {
        while (!sounds.isEmpty() && sounds.peekFirst().end() <= fromSample) {
            sounds.removeFirst();
        }
        short[] out = new short[frames * 2];
        for (int i = 0; i < frames; i++) {
            long at = fromSample + i;
            double signal = 0;
            for (Sound s : sounds) {
                if (at >= s.start() && at < s.end()) {
                    signal += s.pcm()[(int) (at - s.start())];
                }
            }
            out[2 * i] = clip(signal + NOISE_RMS * gaussian());
            out[2 * i + 1] = clip(signal + NOISE_RMS * gaussian());
        }
        return out;
    }

    private double gaussian() {
        // sum of uniforms: cheap, bounded, close enough to normal for background noise
        double s = 0;
        for (int i = 0; i < 4; i++) {
            s += random.nextDouble();
        }
        return (s - 2.0) * Math.sqrt(3.0);
    }

    private static short clip(double v) {
        return (short) Math.max(Short.MIN_VALUE, Math.min(Short.MAX_VALUE, Math.round(v)));
    }
}
