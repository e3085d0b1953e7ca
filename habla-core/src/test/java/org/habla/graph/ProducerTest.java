package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.habla.sample.NumberValue;
import org.junit.jupiter.api.Test;

class ProducerTest {

    @Test
    void subscribersAddedAheadGetEachSampleFirstInTheOrderTheyWereAdded() {
        Producer p = new Producer("s.out");
        List<String> order = new ArrayList<>();
        p.tapFirst(s -> order.add("tap"));
        p.subscribe(s -> order.add("woken 1"));
        p.subscribeAhead(s -> order.add("inline 1"));
        p.subscribe(s -> order.add("woken 2"));
        p.subscribeAhead(s -> order.add("inline 2"));
        p.publish(new NumberValue(1), 1, false);
        assertThat(order).containsExactly("tap", "inline 1", "inline 2", "woken 1", "woken 2");
    }

    @Test
    void everySampleIsNumberedAndTheNewestKept() {
        Producer p = new Producer("s.out");
        p.publish(new NumberValue(1), 1, false);
        p.publish(new NumberValue(2), 2, true);
        assertThat(p.published()).isEqualTo(2);
        assertThat(p.latest().sequence()).isEqualTo(2);
        assertThat(p.latest().stale()).isTrue();
        assertThat(p.latest().producer()).isEqualTo("s.out");
    }
}
