package org.habla.drivers.pioneer;

/**
 * One odometry coordinate kept continuous across the SIP's 15-bit roll-over. Each raw value is compared
 * with the previous one; the step, taken modulo 2^15 into -2^14..2^14-1, is added to a running total.
 * The first value sets the start, read as a signed 15-bit number so a robot that has backed up from 0
 * starts just below 0, not 39 m away.
 *
 * <p>A step is assumed to be shorter than half the 15-bit range (about 13.8 m on a P2DX); at a SIP every
 * 100 ms that is far above any Pioneer's speed.
 */
final class RollingPosition {

    private static final int MASK = 0x7FFF;
    private static final int HALF = 0x4000;

    private boolean started;
    private int lastRaw;
    private long total;

    /** Takes the next raw 15-bit value; returns the continuous position in raw units. */
    long update(int raw) {
        int r = raw & MASK;
        if (!started) {
            started = true;
            total = r >= HALF ? r - 0x8000 : r;
        } else {
            int step = (r - lastRaw) & MASK;
            if (step >= HALF) {
                step -= 0x8000;
            }
            total += step;
        }
        lastRaw = r;
        return total;
    }
}
