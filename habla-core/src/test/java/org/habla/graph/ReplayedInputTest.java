package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.Test;

class ReplayedInputTest {

    private final List<Long> told = new CopyOnWriteArrayList<>();

    private static Sample number(int n) {
        return new Sample(new NumberValue(n), "@robot.value", n, n, false);
    }

    private static Input<?> input() {
        return new TestMethods.AddOneProcessing().in;
    }

    private InputSlot slot(Delivery delivery) {
        return new InputSlot(input(), delivery, InputSlot.Taker.waking(() -> { }), WorkCount.NONE, told::add);
    }

    private static List<Double> drain(InputSlot slot) {
        List<Double> got = new ArrayList<>();
        for (Sample s = slot.poll(); s != null; s = slot.poll()) {
            got.add(((NumberValue) s.payload()).value());
        }
        return got;
    }

    @Test
    void aQueueInputDropsTheArrivalsTheRecordedRunDroppedAndNoOther() {
        InputSlot slot = slot(Delivery.queue(8));
        Set<Long> recorded = Set.of(2L, 4L);
        ReplayedInput in = new ReplayedInput("p", slot, (method, input, arrival) ->
                method.equals("p") && input.equals("in") && recorded.contains(arrival));
        List<Boolean> taken = new ArrayList<>();
        for (int i = 1; i <= 5; i++) {
            taken.add(in.offer(number(i)));
        }
        assertThat(taken).containsExactly(true, false, true, false, true);
        assertThat(drain(slot)).containsExactly(1.0, 3.0, 5.0);
        assertThat(slot.dropped()).isEqualTo(2);
        assertThat(slot.offered()).isEqualTo(5);
        assertThat(told).as("what a recording of the replay says was skipped").containsExactly(2L, 4L);
    }

    @Test
    void aLatestInputCountsARecordedSkipAsReplacedAndKeepsNumberingTheArrivals() {
        InputSlot slot = slot(Delivery.latest());
        ReplayedInput in = new ReplayedInput("p", slot, (method, input, arrival) -> arrival == 1);
        assertThat(in.offer(number(1))).isTrue();
        assertThat(slot.isEmpty()).as("the skipped first sample never reached the slot").isTrue();
        assertThat(in.offer(number(2))).isTrue();
        assertThat(in.offer(number(3))).isTrue();
        assertThat(drain(slot)).containsExactly(3.0);
        assertThat(slot.conflated()).isEqualTo(2);
        assertThat(told).as("the recorded skip, then the one the slot replaced").containsExactly(1L, 2L);
    }

    @Test
    void aLiveSlotNumbersItsArrivalsAsAReplayedOneDoes() {
        InputSlot slot = slot(Delivery.queue(2));
        for (int i = 1; i <= 4; i++) {
            slot.offer(number(i));
        }
        assertThat(drain(slot)).containsExactly(1.0, 2.0);
        assertThat(told).as("the third and fourth arrival found the queue of two full").containsExactly(3L, 4L);
    }
}
