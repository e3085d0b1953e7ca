package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.DoubleConsumer;
import org.habla.method.Delivery;
import org.habla.method.Input;
import org.habla.method.InputPort;
import org.habla.method.MethodState;
import org.habla.method.ProcessingMethod;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A method run by the thread that delivers to it: one message at a time whoever delivers, and its input's delivery
 * kept — a sample that comes back while the method handles waits in the slot as it would for a method's own thread.
 */
@Timeout(30)
class InlineSchedulerTest {

    /** Writes down what it handles, on which thread and how deep in its own handler; runs {@link #during} inside. */
    static final class Witness extends ProcessingMethod {
        final Input<NumberValue> in;
        final List<Double> handled = new CopyOnWriteArrayList<>();
        final List<String> threads = new CopyOnWriteArrayList<>();
        final AtomicInteger depth = new AtomicInteger();
        volatile int deepest;
        volatile DoubleConsumer during = v -> { };

        Witness(Delivery delivery) {
            in = input(InputPort.of("in", NumberValue.class, delivery), this::on);
        }

        private void on(NumberValue v, Sample s) {
            deepest = Math.max(deepest, depth.incrementAndGet());
            try {
                handled.add(v.value());
                threads.add(Thread.currentThread().getName());
                during.accept(v.value());
            } finally {
                depth.decrementAndGet();
            }
        }
    }

    private final ExecutorService pool = BackgroundPool.create("inline-test-");
    private final WorkCount work = new WorkCount();

    @AfterEach
    void shutDown() {
        pool.shutdownNow();
    }

    private MethodRunner runner(Witness w) {
        return new MethodRunner("w", "witness", w, new ManualClock(1_000_000), pool, work, GraphTap.NONE, Set.of(),
                new ThreadPlan.Choice("w", true, true, "test-feeder", "fed by the test"));
    }

    private static Sample number(double v) {
        return new Sample(new NumberValue(v), "test.out", (long) v, 1_000_000, false);
    }

    private static boolean offer(MethodRunner r, Witness w, double v) {
        return r.slot(w.in).offer(number(v));
    }

    @Test
    void aSampleThatComesBackWhileTheMethodHandlesIsHandledAfterTheHandlerReturnsInOrder() throws Exception {
        Witness w = new Witness(Delivery.queue(8));
        MethodRunner r = runner(w);
        r.start();
        w.during = v -> {
            if (v == 1) {
                offer(r, w, 2);
                offer(r, w, 3);
                assertThat(w.handled).as("not handled inside the handler").containsExactly(1.0);
            }
        };
        offer(r, w, 1);
        assertThat(w.handled).as("all handled before the first delivery returned").containsExactly(1.0, 2.0, 3.0);
        assertThat(w.deepest).as("never inside itself").isEqualTo(1);
        assertThat(w.threads).containsOnly(Thread.currentThread().getName());
        assertThat(work.awaitIdle(1_000)).as("every sample counted in was counted out").isTrue();
        r.stop(1_000);
    }

    @Test
    void aLatestInputKeepsOnlyTheNewestOfWhatCameBackMeanwhile() {
        Witness w = new Witness(Delivery.latest());
        MethodRunner r = runner(w);
        r.start();
        w.during = v -> {
            if (v == 1) {
                offer(r, w, 2);
                offer(r, w, 3);
            }
        };
        offer(r, w, 1);
        assertThat(w.handled).containsExactly(1.0, 3.0);
        assertThat(r.status(0).path("inputs").path("in").path("conflated").asLong()).isEqualTo(1);
        r.stop(1_000);
    }

    @Test
    void aFullQueueDropsWhatCameBackMeanwhileAndCountsIt() {
        Witness w = new Witness(Delivery.queue(1));
        MethodRunner r = runner(w);
        r.start();
        List<Boolean> taken = new CopyOnWriteArrayList<>();
        w.during = v -> {
            if (v == 1) {
                taken.add(offer(r, w, 2));
                taken.add(offer(r, w, 3));
            }
        };
        offer(r, w, 1);
        assertThat(taken).containsExactly(true, false);
        assertThat(w.handled).containsExactly(1.0, 2.0);
        assertThat(r.status(0).path("inputs").path("in").path("dropped").asLong()).isEqualTo(1);
        r.stop(1_000);
    }

    @Test
    void aSecondThreadThatDeliversWhileTheMethodIsHeldLeavesItsSampleToTheHolder() throws Exception {
        Witness w = new Witness(Delivery.queue(8));
        MethodRunner r = runner(w);
        r.start();
        CountDownLatch gate = new CountDownLatch(1);
        CountDownLatch holding = new CountDownLatch(1);
        w.during = v -> {
            if (v == 1) {
                holding.countDown();
                try {
                    gate.await(20, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        };
        Thread first = Thread.ofPlatform().name("first-feeder").start(() -> offer(r, w, 1));
        assertThat(holding.await(20, TimeUnit.SECONDS)).isTrue();
        assertThat(offer(r, w, 2)).as("the second delivery returns at once").isTrue();
        assertThat(w.handled).as("nothing handled beside the held sample").containsExactly(1.0);
        gate.countDown();
        first.join(20_000);
        assertThat(w.handled).containsExactly(1.0, 2.0);
        assertThat(w.threads).as("the holder took the second sample").containsOnly("first-feeder");
        assertThat(w.deepest).isEqualTo(1);
        r.stop(1_000);
    }

    @Test
    void whatArrivesBeforeTheStartIsHandledAtTheStartAndNothingAfterTheStop() {
        Witness w = new Witness(Delivery.queue(8));
        MethodRunner r = runner(w);
        offer(r, w, 1);
        assertThat(w.handled).as("not started").isEmpty();
        r.start();
        assertThat(w.handled).containsExactly(1.0);
        r.stop(1_000);
        assertThat(r.state()).isEqualTo(MethodState.STOPPED);
        offer(r, w, 2);
        assertThat(w.handled).as("stopped").containsExactly(1.0);
    }

    @Test
    void aTimedPassThatTakesTooMuchOfTheDeliveringThreadsProcessorIsCounted() {
        Witness w = new Witness(Delivery.queue(8));
        MethodRunner r = runner(w);
        r.start();
        double timed = InlineScheduler.TIMED_EVERY - 1; // the value handled in the first timed pass
        w.during = v -> {
            if (v == timed) {
                // a method that works longer than a light one may: processor time, however busy the machine
                var cpu = java.lang.management.ManagementFactory.getThreadMXBean();
                long until = cpu.getCurrentThreadCpuTime()
                        + TimeUnit.MICROSECONDS.toNanos(3 * InlineScheduler.OVERRUN_MICROS);
                double x = 0;
                while (cpu.getCurrentThreadCpuTime() < until) {
                    x += Math.sqrt(x + v);
                }
                w.threads.add("spun " + (x > 0));
            }
        };
        for (int i = 0; i < InlineScheduler.TIMED_EVERY; i++) {
            offer(r, w, i);
        }
        var thread = r.status(0).path("thread");
        assertThat(thread.path("overruns").asLong()).as("the one timed pass").isEqualTo(1);
        assertThat(thread.path("longestTimedPassCpuUs").asLong()).isGreaterThan(InlineScheduler.OVERRUN_MICROS);
        w.during = v -> { };
        for (int i = 0; i < InlineScheduler.TIMED_EVERY; i++) {
            offer(r, w, i);
        }
        assertThat(r.status(0).path("thread").path("overruns").asLong()).as("a quick pass timed next").isEqualTo(1);
        r.stop(1_000);
    }
}
