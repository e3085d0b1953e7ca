package org.habla.method;

/**
 * How samples wait for a method on one input.
 *
 * <ul>
 *   <li>{@code latest}: one slot; a newer sample replaces one not yet handled (sensor streams).
 *       Replaced samples are counted as conflated, which is the intent, not a loss.</li>
 *   <li>{@code queue}: a bounded first-in first-out queue (commands, audio). A sample that finds
 *       the queue full is dropped and counted; the count is reported in the status.</li>
 * </ul>
 */
public record Delivery(Mode mode, int capacity) {

    /** The largest queue an input may ask for. */
    public static final int MAX_CAPACITY = 65_536;

    public enum Mode { LATEST, QUEUE }

    public Delivery {
        if (mode == Mode.LATEST && capacity != 1) {
            throw new IllegalArgumentException("a latest input holds exactly one sample");
        }
        if (capacity < 1 || capacity > MAX_CAPACITY) {
            throw new IllegalArgumentException("queue capacity must be in 1.." + MAX_CAPACITY + ", was " + capacity);
        }
    }

    public static Delivery latest() {
        return new Delivery(Mode.LATEST, 1);
    }

    public static Delivery queue(int capacity) {
        return new Delivery(Mode.QUEUE, capacity);
    }
}
