package org.habla.graph;

import org.habla.sample.Sample;

/**
 * Where a wire or a control write hands the samples of one method's input: in a live graph the input's
 * {@link InputSlot} itself, in a replay a {@link ReplayedInput} in front of it. Never blocks.
 */
@FunctionalInterface
interface InputEntry {

    /** Hands a sample to the input; false if a full queue dropped it. */
    boolean offer(Sample sample);
}
