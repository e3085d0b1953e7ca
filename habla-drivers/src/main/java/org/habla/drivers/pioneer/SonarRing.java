package org.habla.drivers.pioneer;

import java.util.Arrays;

/**
 * The latest range of every sonar transducer, merged from SIPs that each carry only some of them (a real
 * robot sends the readings that are new since the last SIP).
 *
 * <p>The ring is first {@link #ready} once every transducer has reported, or, if some never do (a
 * disabled array), after {@value #PATIENCE_UPDATES} updates; transducers that have not reported read as
 * the maximum range until they do.
 */
final class SonarRing {

    /** Updates to wait for a complete ring before publishing a partial one (about 1 s of SIPs). */
    static final int PATIENCE_UPDATES = 10;

    private final double[] rangesM;
    private final boolean[] seen;
    private int seenCount;
    private int updates;

    SonarRing(int count, double unseenM) {
        rangesM = new double[count];
        Arrays.fill(rangesM, unseenM);
        seen = new boolean[count];
    }

    int size() {
        return rangesM.length;
    }

    /** Stores one reading; false if the index is not a transducer of this robot. */
    boolean put(int index, double rangeM) {
        if (index < 0 || index >= rangesM.length) {
            return false;
        }
        rangesM[index] = rangeM;
        if (!seen[index]) {
            seen[index] = true;
            seenCount++;
        }
        return true;
    }

    /** Marks the end of one SIP's readings. */
    void endUpdate() {
        updates++;
    }

    boolean ready() {
        return seenCount == rangesM.length || updates >= PATIENCE_UPDATES;
    }

    /** A copy of the ranges, m. */
    double[] snapshot() {
        return rangesM.clone();
    }
}
