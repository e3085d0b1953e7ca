package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

class SlotQueueTest {

    @Test
    void aFullQueueRefusesTheNextValueAndTakesOneAgainOnceTheHeadIsTaken() {
        SlotQueue<String> q = new SlotQueue<>(3);
        assertThat(q.isEmpty()).isTrue();
        assertThat(q.offer("a")).isTrue();
        assertThat(q.offer("b")).isTrue();
        assertThat(q.offer("c")).isTrue();
        assertThat(q.offer("d")).as("a fourth value in a queue of three").isFalse();
        assertThat(q.size()).isEqualTo(3);
        assertThat(q.poll()).isEqualTo("a");
        assertThat(q.offer("e")).isTrue();
        assertThat(List.of(q.poll(), q.poll(), q.poll())).containsExactly("b", "c", "e");
        assertThat(q.poll()).isNull();
        assertThat(q.isEmpty()).isTrue();
        assertThat(q.size()).isZero();
    }

    @Test
    void aQueueOfOneHoldsOneValueLapAfterLap() {
        SlotQueue<Integer> q = new SlotQueue<>(1);
        for (int i = 0; i < 10; i++) {
            assertThat(q.offer(i)).isTrue();
            assertThat(q.offer(-i)).as("second value, lap %d", i).isFalse();
            assertThat(q.size()).isEqualTo(1);
            assertThat(q.poll()).isEqualTo(i);
            assertThat(q.poll()).isNull();
        }
    }

    @Test
    void valuesFromManyProducersArriveOnceEachAndInEachProducersOrder() throws Exception {
        int producers = 4;
        int each = 50_000;
        SlotQueue<long[]> q = new SlotQueue<>(64);
        AtomicLong refused = new AtomicLong();
        List<Thread> threads = new ArrayList<>();
        for (int p = 0; p < producers; p++) {
            long id = p;
            threads.add(Thread.ofPlatform().start(() -> {
                for (long i = 0; i < each; ) {
                    if (q.offer(new long[] {id, i})) {
                        i++;
                    } else {
                        refused.incrementAndGet();
                        Thread.onSpinWait();
                    }
                }
            }));
        }
        long[] next = new long[producers];
        long taken = 0;
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (taken < (long) producers * each) {
            assertThat(System.nanoTime()).as("all values taken within 60 s").isLessThan(deadline);
            long[] v = q.poll();
            if (v == null) {
                Thread.onSpinWait();
                continue;
            }
            assertThat(v[1]).as("next value of producer %d", v[0]).isEqualTo(next[(int) v[0]]);
            next[(int) v[0]]++;
            taken++;
        }
        for (Thread t : threads) {
            t.join(10_000);
            assertThat(t.isAlive()).isFalse();
        }
        assertThat(q.poll()).isNull();
        assertThat(q.isEmpty()).isTrue();
        assertThat(next).containsOnly(each);
    }
}
