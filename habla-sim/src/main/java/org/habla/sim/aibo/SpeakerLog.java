package org.habla.sim.aibo;

/**
 * What the robot said through its speaker: how much PCM arrived, when, and how loud. The ground truth
 * reports it, so a test or a scenario can tell that the robot spoke.
 */
public final class SpeakerLog {

    /** A summary: packets and seconds of sound received, the last packet's time and peak level (0..1). */
    public record Summary(long packets, double seconds, double lastAtS, double lastPeak, long rejected) {
    }

    private long packets;
    private double seconds;
    private double lastAtS = -1;
    private double lastPeak;
    private long rejected;

    synchronized void heard(int rateHz, double peak, int samples, double atS) {
        packets++;
        seconds += (double) samples / rateHz;
        lastAtS = atS;
        lastPeak = peak;
    }

    synchronized void rejected() {
        rejected++;
    }

    public synchronized Summary summary() {
        return new Summary(packets, seconds, lastAtS, lastPeak, rejected);
    }
}
