package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Random;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;

class LatencyStatsTest {

    @Test
    void everyValueFallsInABucketWhoseHighestValueIsWithinOneHundredTwentyEighthOfIt() {
        Random random = new Random(7);
        int previous = -1;
        for (long v = 0; v < 5_000; v++) {
            int i = LatencyStats.index(v);
            assertThat(i).as("buckets follow the values (%d)", v).isGreaterThanOrEqualTo(previous);
            previous = i;
            assertThat(LatencyStats.highestIn(i)).as("bucket of %d", v)
                    .isGreaterThanOrEqualTo(v).isLessThanOrEqualTo(v + v / 128);
        }
        for (int n = 0; n < 100_000; n++) {
            long v = (long) (random.nextDouble() * LatencyStats.MAX_MICROS);
            long high = LatencyStats.highestIn(LatencyStats.index(v));
            assertThat(high).as("bucket of %d", v).isGreaterThanOrEqualTo(v).isLessThanOrEqualTo(v + v / 128);
            assertThat(LatencyStats.index(high)).isEqualTo(LatencyStats.index(v));
            assertThat(LatencyStats.index(high + 1)).isEqualTo(LatencyStats.index(v) + 1);
        }
    }

    @Test
    void percentilesAreOverWhatWasRecordedSinceThePreviousRead() {
        LatencyStats stats = new LatencyStats();
        assertThat(stats.snapshot().get("count").asLong()).isZero();
        assertThat(stats.snapshot().has("p50Us")).as("no percentiles of nothing").isFalse();
        for (int v = 1; v <= 100; v++) {
            stats.record(v);
        }
        ObjectNode first = stats.snapshot();
        assertThat(first.get("count").asLong()).isEqualTo(100);
        assertThat(first.get("p50Us").asLong()).isEqualTo(50);
        assertThat(first.get("p99Us").asLong()).isEqualTo(99);
        assertThat(first.get("maxUs").asLong()).isEqualTo(100);

        for (int n = 0; n < 99; n++) {
            stats.record(10_000);
        }
        stats.record(-5); // a clock that went back: counted as 0
        ObjectNode second = stats.snapshot();
        assertThat(second.get("count").asLong()).isEqualTo(100);
        assertThat(second.get("p50Us").asLong()).isBetween(10_000L, 10_000L + 10_000 / 128);
        assertThat(second.get("maxUs").asLong()).isBetween(10_000L, 10_000L + 10_000 / 128);

        stats.record(Long.MAX_VALUE);
        assertThat(stats.snapshot().get("maxUs").asLong()).as("kept at the highest value recorded")
                .isGreaterThanOrEqualTo(LatencyStats.MAX_MICROS);
        assertThat(stats.snapshot().get("count").asLong()).isZero();
    }

    @Test
    void readsWhileOneThreadRecordsLoseNoValueAndCountNoneTwice() throws InterruptedException {
        LatencyStats stats = new LatencyStats();
        int values = 2_000_000;
        AtomicBoolean done = new AtomicBoolean();
        Thread writer = new Thread(() -> {
            for (int n = 0; n < values; n++) {
                stats.record(n % 3_000);
            }
            done.set(true);
        });
        writer.start();
        long counted = 0;
        int reads = 0;
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (!done.get() && System.nanoTime() - deadline < 0) {
            counted += stats.snapshot().get("count").asLong();
            reads++;
        }
        writer.join(60_000);
        assertThat(done).as("the writer finished").isTrue();
        counted += stats.snapshot().get("count").asLong();
        assertThat(counted).as("over %d reads", reads).isEqualTo(values);
    }
}
