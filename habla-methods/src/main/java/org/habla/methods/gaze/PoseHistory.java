package org.habla.methods.gaze;

import java.util.ArrayDeque;
import java.util.Iterator;

/**
 * The head's recent poses with the times of their readings, so that an image can be matched with
 * where the head pointed when it was taken rather than where it points now: camera frames reach a
 * method later than the joint readings of the same moment, and a head that moves meanwhile would
 * otherwise skew every bearing measured in the image. Holds the last {@link #CAPACITY} poses.
 */
public final class PoseHistory {

    /** How many poses are kept: about two seconds of joint readings at 31 Hz. */
    public static final int CAPACITY = 64;

    private record Entry(long micros, HeadPose pose) {
    }

    private final ArrayDeque<Entry> entries = new ArrayDeque<>();

    /** Adds a pose read at {@code micros}; a reading older than the newest is ignored. */
    public void add(long micros, HeadPose pose) {
        if (!entries.isEmpty() && micros < entries.peekLast().micros()) {
            return;
        }
        entries.addLast(new Entry(micros, pose));
        if (entries.size() > CAPACITY) {
            entries.removeFirst();
        }
    }

    /** The pose at {@code micros}: the last one read at or before it, else the oldest; null when empty. */
    public HeadPose at(long micros) {
        HeadPose found = null;
        for (Iterator<Entry> it = entries.descendingIterator(); it.hasNext();) {
            Entry e = it.next();
            found = e.pose();
            if (e.micros() <= micros) {
                break;
            }
        }
        return found;
    }

    /** The newest pose, or null when empty. */
    public HeadPose latest() {
        return entries.isEmpty() ? null : entries.peekLast().pose();
    }
}
