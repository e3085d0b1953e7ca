package org.habla.graph;

/**
 * What a replay tells the engine that timing decided in the recorded run: which samples offered to a method's input
 * never reached the method (a {@code latest} input replaced them, a full {@code queue} dropped them). A graph built
 * on a recording ({@link MethodGraph#replaying}) skips the same arrivals, so each method handles the same samples
 * as when it was recorded; a live graph never asks. What the recording module reads from its file and hands to
 * the engine; the engine side of the seam is {@link GraphReplay}.
 */
@FunctionalInterface
public interface RecordedSkips {

    /**
     * Whether the recorded run skipped the {@code arrival}-th sample offered to {@code methodId}'s {@code input}
     * (1 for the first), as {@link GraphTap#skipped} told it.
     */
    boolean skipped(String methodId, String input, long arrival);

    /** A recording in which no sample was skipped. */
    RecordedSkips NONE = (methodId, input, arrival) -> false;
}
