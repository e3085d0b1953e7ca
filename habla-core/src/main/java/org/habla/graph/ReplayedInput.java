package org.habla.graph;

import org.habla.sample.Sample;

/**
 * A replayed method's input: every sample that reaches the input takes its place in the order of arrival, and one
 * the recorded run skipped ({@link RecordedSkips}) is skipped here too — counted as its slot counts a sample it
 * replaces or drops, and told to the tap — where live timing would have decided. The others go on to the slot.
 */
final class ReplayedInput implements InputEntry {

    private final String methodId;
    private final InputSlot slot;
    private final RecordedSkips skips;

    ReplayedInput(String methodId, InputSlot slot, RecordedSkips skips) {
        this.methodId = methodId;
        this.slot = slot;
        this.skips = skips;
    }

    @Override
    public boolean offer(Sample sample) {
        long arrival = slot.arrive();
        if (skips.skipped(methodId, slot.input().name(), arrival)) {
            return slot.skip(arrival);
        }
        return slot.offer(sample, arrival);
    }
}
