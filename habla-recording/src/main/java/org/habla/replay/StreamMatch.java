package org.habla.replay;

/**
 * How one stream of the replay (an exposed output, or the commands to the hardware) compares with the
 * recorded one, value by value in order.
 *
 * @param name            {@code method.output}, or {@code commands}
 * @param recorded        values in the recording
 * @param replayed        values the replay produced
 * @param identical       positions where both have the same value
 * @param firstDifference the first position where they differ (or where one ran out), -1 if none
 */
public record StreamMatch(String name, int recorded, int replayed, int identical, int firstDifference) {

    /** The same values in the same order, and as many. */
    public boolean matches() {
        return firstDifference < 0;
    }

    @Override
    public String toString() {
        return name + ": " + (matches() ? "all " + recorded + " identical"
                : identical + " of " + recorded + " recorded identical (" + replayed + " replayed), first difference at #"
                        + firstDifference);
    }
}
