package org.habla.bench;

import java.util.concurrent.atomic.LongAdder;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.graph.ManualClock;
import org.habla.graph.MethodGraph;
import org.habla.method.Input;
import org.habla.method.Output;
import org.habla.net.ControlPoint;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;

/**
 * Benchmark (b): samples per second through a chain of three methods in one process, no sockets:
 * a producer thread writes numbers into a virtual method's control input; they pass
 * {@code pass-through} (virtual) → {@code pass-through} (processing) → {@code pass-through} (virtual),
 * every input a bounded queue; a listener counts what leaves the last one. A write the first queue refuses
 * (full) is retried, so nothing is lost and the rate is what the chain sustains. The first method has a thread of
 * its own (control clients write to it), and the two light ones after it run on that thread; then the same chain
 * with each method on a thread of its own ({@code "thread": "own"}).
 */
final class ThroughputBench {

    private final int warmupS;
    private final int seconds;

    ThroughputBench(int warmupS, int seconds) {
        this.warmupS = warmupS;
        this.seconds = seconds;
    }

    void run() throws Exception {
        System.out.printf("%n(b) in-process throughput, 3-method chain on queue inputs (capacity 4096), %d s warm-up, %d s measured%n",
                warmupS, seconds);
        chain("the two light methods on the first one's thread", "");
        chain("each method on its own thread", ", \"thread\": \"own\"");
    }

    /** One chain, each method's entry ending with {@code thread}. */
    private void chain(String label, String thread) throws Exception {
        System.out.printf("  %s:%n", label);
        String relay = "\"params\": {\"kind\": \"number\", \"delivery\": \"queue\", \"capacity\": 4096}" + thread;
        String json = """
                {"system": "bench-throughput", "status": {"port": 0},
                 "methods": [
                   {"id": "in", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"}, %s,
                    "expose": {"port": 7001, "name": "in"}},
                   {"id": "p", "type": "pass-through", "layer": "processing", "inputs": {"in": "in.out"}, %s},
                   {"id": "out", "type": "pass-through", "layer": "virtual", "inputs": {"in": "p.out"}, %s,
                    "expose": {"port": 7002, "name": "out"}}
                 ]}
                """.formatted(relay, relay, relay);
        PluginRegistry registry = PluginRegistry.discover();
        HablaConfig config = new ConfigLoader(registry).parse(json);
        ManualClock clock = new ManualClock(1_700_000_000_000_000L);
        try (MethodGraph graph = MethodGraph.build(config, registry, clock)) {
            graph.start();
            ControlPoint in = point(graph, "in");
            ControlPoint out = point(graph, "out");
            Input<?> input = in.controlInputs().get(0);
            LongAdder received = new LongAdder();
            out.subscribe(new ControlPoint.Listener() {
                @Override
                public void onSample(Output<?> output, Sample sample) {
                    received.increment();
                }

                @Override
                public void onStale(boolean stale, String why) {
                }
            });
            LongAdder refused = new LongAdder();
            Thread producer = Thread.ofPlatform().name("bench-producer").start(() -> produce(in, input, refused));
            try {
                Thread.sleep(warmupS * 1000L);
                long r0 = received.sum();
                long f0 = refused.sum();
                long cpu0 = processCpuNanos();
                long t0 = System.nanoTime();
                Thread.sleep(seconds * 1000L);
                long r1 = received.sum();
                long f1 = refused.sum();
                long cpu1 = processCpuNanos();
                double s = (System.nanoTime() - t0) / 1e9;
                System.out.printf("    %,.0f samples/s through the chain (%,d in %.1f s); the producer found the first queue full %,d times%n",
                        (r1 - r0) / s, r1 - r0, s, f1 - f0);
                System.out.printf("    processor time of the whole process per sample: %.2f µs (less sensitive to other processes than the rate)%n",
                        (cpu1 - cpu0) / 1e3 / Math.max(1, r1 - r0));
            } finally {
                producer.interrupt();
                producer.join(5_000);
            }
        }
    }

    private static long processCpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    private static ControlPoint point(MethodGraph g, String name) {
        return g.controlPoints().stream().filter(p -> p.name().equals(name)).findFirst().orElseThrow();
    }

    private static void produce(ControlPoint in, Input<?> input, LongAdder refused) {
        long n = 0;
        NumberValue[] values = new NumberValue[1024];
        for (int i = 0; i < values.length; i++) {
            values[i] = new NumberValue(i);
        }
        while (!Thread.currentThread().isInterrupted()) {
            try {
                in.write(input, values[(int) (n & 1023)]);
                n++;
            } catch (ControlPoint.Rejected e) {
                // The first queue is full: wait a little, as a well-behaved client does, rather than spin on a
                // core the chain needs (4 096 queued samples last about 2 ms at 2 M/s; the wait is 20 µs).
                refused.increment();
                java.util.concurrent.locks.LockSupport.parkNanos(20_000);
            }
        }
    }
}
