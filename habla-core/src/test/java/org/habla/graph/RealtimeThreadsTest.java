package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.habla.net.Expose;
import org.habla.config.HablaConfig;
import org.habla.config.InterfaceConfig;
import org.habla.net.Limits;
import org.habla.config.MethodConfig;
import org.habla.config.Reconnect;
import org.habla.config.Safety;
import org.habla.config.Source;
import org.habla.config.StatusConfig;
import org.habla.driver.InterfaceAddress;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.net.ControlPoint;
import org.habla.plugin.NoParams;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.Test;

class RealtimeThreadsTest {

    @Test
    void thePriorityIsZeroUnsetOrOneTo99AndAnythingElseIsRefusedNamingTheProperty() {
        assertThat(RealtimeThreads.priority(null)).isZero();
        assertThat(RealtimeThreads.priority(" ")).isZero();
        assertThat(RealtimeThreads.priority("0")).isZero();
        assertThat(RealtimeThreads.priority(" 10 ")).isEqualTo(10);
        assertThat(RealtimeThreads.priority("99")).isEqualTo(99);
        for (String wrong : new String[] {"100", "-1", "high"}) {
            assertThatThrownBy(() -> RealtimeThreads.priority(wrong))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("-Dhabla.realtimePriority")
                    .hasMessageContaining("'" + wrong + "'");
        }
    }

    /**
     * Where the process may (as root, or with an rtprio limit) the thread ends in SCHED_FIFO and a thread it starts
     * does not; where it may not, the thread says so and stays normal. As root it must succeed.
     */
    @Test
    void aRaisedThreadRunsFirstInFirstOutAndTheThreadsItStartsRunNormally() throws Exception {
        AtomicBoolean raised = new AtomicBoolean();
        AtomicReference<OptionalInt> policy = new AtomicReference<>();
        AtomicReference<OptionalInt> childPolicy = new AtomicReference<>();
        Thread t = Thread.ofPlatform().start(() -> {
            raised.set(RealtimeThreads.raiseCurrent(10));
            policy.set(RealtimeThreads.policy(ThreadNice.threadId().orElseThrow()));
            Thread child = Thread.ofPlatform().start(() ->
                    childPolicy.set(RealtimeThreads.policy(ThreadNice.threadId().orElseThrow())));
            try {
                child.join(10_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        t.join(30_000);
        assertThat(t.isAlive()).isFalse();
        assertThat(policy.get()).isPresent();
        assertThat(policy.get().getAsInt() == RealtimeThreads.SCHED_FIFO).isEqualTo(raised.get());
        assertThat(childPolicy.get()).hasValue(0);
        if (isRoot()) {
            assertThat(raised.get()).as("root may set SCHED_FIFO").isTrue();
        }
    }

    @Test
    void theCarriersOfVirtualThreadsAreFoundByTheirName() {
        String prefix = RealtimeThreads.carrierPrefix();
        assertThat(prefix).isNotNull().endsWith("-");
        AtomicReference<String> name = new AtomicReference<>();
        Thread v = Thread.ofVirtual().start(() -> name.set(Thread.currentThread().toString()));
        try {
            v.join(5_000);
        } catch (InterruptedException e) {
            throw new AssertionError(e);
        }
        assertThat(name.get()).contains("@" + prefix);
    }

    /**
     * With the property set, a graph's method thread, link thread and the carriers of virtual threads run first in
     * first out where the process may (as root it must), and readings still climb to the socket.
     */
    @Test
    void withThePropertySetTheSamplePathOfAGraphRunsRealTime() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        HablaConfig config = new HablaConfig("test", Limits.DEFAULTS, new Safety(0), new StatusConfig("127.0.0.1", 0),
                List.of(new InterfaceConfig("rt", "lines-test", new InterfaceAddress("127.0.0.1",
                        OptionalInt.of(robot.port())), new NoParams(), new Reconnect(50, 200, 1_000, 5_000))),
                List.of(new MethodConfig("r", "add-one-virtual", Layer.VIRTUAL, Map.of("in", new Source.Channel("rt",
                        "value")), Map.of(), new NoParams(), Optional.of(new Expose("r", "127.0.0.1", 0)),
                        Optional.empty())));
        System.setProperty(RealtimeThreads.PROPERTY, "10");
        MethodGraph g;
        try {
            g = MethodGraph.build(config, TestMethods.registry(), EngineClock.system());
            g.start();
        } finally {
            System.clearProperty(RealtimeThreads.PROPERTY);
        }
        try (robot; g) {
            BlockingQueue<Sample> seen = new LinkedBlockingQueue<>();
            g.controlPoints().get(0).subscribe(new ControlPoint.Listener() {
                @Override
                public void onSample(Output<?> output, Sample sample) {
                    seen.add(sample);
                }

                @Override
                public void onStale(boolean stale, String why) {
                }
            });
            assertThat(robot.awaitClient(30_000)).isTrue();
            robot.send("value 1");
            Sample s = seen.poll(30, TimeUnit.SECONDS);
            assertThat(s).isNotNull();
            assertThat(s.payload()).isEqualTo(new NumberValue(2));
            String carriers = RealtimeThreads.carrierPrefix().substring(0, 15);
            for (String thread : new String[] {"habla-method-r", "habla-link-rt/", carriers}) {
                if (isRoot()) {
                    assertThat(awaitPolicy(thread, RealtimeThreads.SCHED_FIFO)).as(thread).isTrue();
                } else {
                    assertThat(awaitPolicy(thread, 0)).as(thread + " stays normal").isTrue();
                }
            }
        }
        // Closed, the graph hands the carriers back to normal scheduling: they serve the whole JVM.
        String carriers = RealtimeThreads.carrierPrefix().substring(0, 15);
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (withPolicy(carriers, RealtimeThreads.SCHED_FIFO)) {
            assertThat(System.nanoTime()).as("carriers back to normal").isLessThan(end);
            Thread.sleep(50);
        }
    }

    /**
     * A thread that ends between the carriers' sweep listing it and reading its name is not a refusal: the sweep
     * goes on (under load, one did end so, and the sweep then gave up the real-time class for the whole process).
     */
    @Test
    void aThreadThatEndedWhileTheSweepLookedIsPassedOver() {
        assertThat(RealtimeThreads.startsWith(Path.of("/proc/self/task/" + Integer.MAX_VALUE), "ForkJoinPool"))
                .isFalse();
        assertThat(RealtimeThreads.startsWith(Path.of("/proc/thread-self"), "")).isTrue();
    }

    /** Two graphs in one JVM share the carriers: the first one closed leaves them raised for the other. */
    @Test
    void theCarriersStayRaisedUntilTheLastGraphThatAskedCloses() throws Exception {
        String carriers = RealtimeThreads.carrierPrefix().substring(0, 15);
        AutoCloseable first;
        AutoCloseable second;
        System.setProperty(RealtimeThreads.PROPERTY, "10");
        try {
            first = RealtimeThreads.raiseCarriersIfAsked();
            second = RealtimeThreads.raiseCarriersIfAsked();
        } finally {
            System.clearProperty(RealtimeThreads.PROPERTY);
        }
        int expected = isRoot() ? RealtimeThreads.SCHED_FIFO : 0;
        try {
            assertThat(awaitPolicy(carriers, expected)).isTrue();
            first.close();
            first.close(); // twice is once
            assertThat(withPolicy(carriers, expected)).as("raised while the second graph runs").isTrue();
        } finally {
            second.close();
        }
        assertThat(withPolicy(carriers, RealtimeThreads.SCHED_FIFO)).as("handed back after the last").isFalse();
    }

    /** Waits (bounded) until a thread whose Linux name starts with {@code comm} has {@code policy}. */
    private static boolean awaitPolicy(String comm, int policy) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (System.nanoTime() < end) {
            if (withPolicy(comm, policy)) {
                return true;
            }
            Thread.sleep(50);
        }
        return false;
    }

    /** Whether a thread whose Linux name starts with {@code comm} has {@code policy} now. */
    private static boolean withPolicy(String comm, int policy) throws IOException {
        try (DirectoryStream<Path> tasks = Files.newDirectoryStream(Path.of("/proc/self/task"))) {
            for (Path task : tasks) {
                int tid = Integer.parseInt(task.getFileName().toString());
                if (RealtimeThreads.startsWith(task, comm) && RealtimeThreads.policy(tid).orElse(-1) == policy) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean isRoot() throws IOException {
        return Files.readAllLines(Path.of("/proc/self/status")).stream()
                .anyMatch(l -> l.startsWith("Uid:") && l.split("\\s+")[1].equals("0"));
    }
}
