package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.habla.config.ChannelRef;
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
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class MethodGraphTest {

    /** The bound of every wait for something that must happen: generous, as the suite runs on busy machines. */
    private static final long WAIT_MS = 15_000;

    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
    }

    private static MethodConfig method(String id, String type, Layer layer, Map<String, Source> inputs,
            Map<String, ChannelRef> commands, Expose expose) {
        return new MethodConfig(id, type, layer, inputs, commands, new NoParams(), Optional.ofNullable(expose),
                Optional.empty());
    }

    private static Source out(String id, String output) {
        return new Source.MethodOutput(id, output);
    }

    private static HablaConfig config(int robotPort, long watchdogMs, MethodConfig... methods) {
        List<InterfaceConfig> ifs = robotPort < 0 ? List.of() : List.of(new InterfaceConfig("robot", "lines-test",
                new InterfaceAddress("127.0.0.1", java.util.OptionalInt.of(robotPort)), new NoParams(),
                new Reconnect(50, 200, 1_000, 5_000)));
        return new HablaConfig("test", Limits.DEFAULTS, new Safety(watchdogMs), new StatusConfig("127.0.0.1", 0),
                ifs, List.of(methods));
    }

    private MethodGraph start(HablaConfig config) {
        MethodGraph g = MethodGraph.build(config, TestMethods.registry(), EngineClock.system());
        toClose.add(g);
        g.start();
        return g;
    }

    private static ControlPoint point(MethodGraph g, String name) {
        return g.controlPoints().stream().filter(p -> p.name().equals(name)).findFirst().orElseThrow();
    }

    private static BlockingQueue<Sample> listen(ControlPoint p) {
        BlockingQueue<Sample> q = new LinkedBlockingQueue<>();
        p.subscribe(new ControlPoint.Listener() {
            @Override
            public void onSample(Output<?> output, Sample sample) {
                q.add(sample);
            }

            @Override
            public void onStale(boolean stale, String why) {
            }
        });
        return q;
    }

    @Test
    void aReadingClimbsThreeLayersAndKeepsItsSourceTime() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(config(robot.port(), 0,
                method("s", "add-one-sensor", Layer.SENSORS_ACTUATORS,
                        Map.of("in", new Source.Channel("robot", "value")), Map.of(), null),
                method("p", "add-one-processing", Layer.PROCESSING, Map.of("in", out("s", "out")), Map.of(), null),
                method("v", "add-one-virtual", Layer.VIRTUAL, Map.of("in", out("p", "out")), Map.of(),
                        new Expose("v", "127.0.0.1", 7001))));
        BlockingQueue<Sample> seen = listen(point(g, "v"));
        assertThat(robot.awaitClient(WAIT_MS)).isTrue();
        long before = EngineClock.system().nowMicros();
        robot.send("value 10");
        Sample s = seen.poll(WAIT_MS, TimeUnit.MILLISECONDS);
        assertThat(s).isNotNull();
        assertThat(s.payload()).isEqualTo(new NumberValue(13));
        assertThat(s.producer()).isEqualTo("v.out");
        assertThat(s.sequence()).isEqualTo(1);
        assertThat(s.sourceMicros()).isGreaterThanOrEqualTo(before - 1_000);
        assertThat(s.sourceMicros()).isLessThanOrEqualTo(EngineClock.system().nowMicros());
    }

    @Test
    void queueInputsLoseNothingAndKeepOrder() throws Exception {
        MethodGraph g = start(config(-1, 0,
                method("p", "forward-processing", Layer.PROCESSING, Map.of("in", out("v", "out")), Map.of(), null),
                method("v", "command-virtual", Layer.VIRTUAL, Map.of("in", new Source.Control()), Map.of(),
                        new Expose("v", "127.0.0.1", 7001)),
                method("w", "add-one-virtual", Layer.VIRTUAL, Map.of("in", out("p", "out")), Map.of(),
                        new Expose("w", "127.0.0.1", 7002))));
        BlockingQueue<Sample> seen = listen(point(g, "w"));
        ControlPoint v = point(g, "v");
        int n = 50;
        for (int i = 0; i < n; i++) {
            v.write(v.controlInputs().get(0), new NumberValue(i));
        }
        List<Double> got = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Sample s = seen.poll(WAIT_MS, TimeUnit.MILLISECONDS);
            assertThat(s).isNotNull();
            got.add(((NumberValue) s.payload()).value());
        }
        for (int i = 0; i < n; i++) {
            assertThat(got.get(i)).isEqualTo(i + 1.0);
        }
    }

    @Test
    void aFullQueueRejectsTheWriteAndCountsTheDrop() throws Exception {
        MethodGraph g = start(config(-1, 0,
                method("v", "gated-virtual", Layer.VIRTUAL, Map.of("in", new Source.Control()), Map.of(),
                        new Expose("v", "127.0.0.1", 7001))));
        ControlPoint v = point(g, "v");
        // The method holds the first value it takes; its queue of 64 fills behind it.
        int accepted = 0;
        ControlPoint.Rejected rejected = null;
        while (rejected == null && accepted <= 65) {
            try {
                v.write(v.controlInputs().get(0), new NumberValue(accepted));
                accepted++;
            } catch (ControlPoint.Rejected e) {
                rejected = e;
            }
        }
        assertThat(rejected).as("a write once 64 wait and one is held").isNotNull();
        assertThat(rejected.code()).isEqualTo("queue_full");
        assertThat(accepted).as("the queue's 64, and the one being handled if it was taken already").isBetween(64, 65);
        assertThat(methodStatus(g, "v").path("inputs").path("in").path("dropped").asLong()).isEqualTo(1);
        ((TestMethods.GatedVirtual) g.method("v")).gate.countDown();
    }

    @Test
    void aSlowMethodDoesNotHoldUpALightOne() throws Exception {
        MethodGraph g = start(config(-1, 0,
                method("slow", "slow", Layer.PROCESSING, Map.of("in", out("v", "out")), Map.of(), null),
                method("fast", "forward-processing", Layer.PROCESSING, Map.of("in", out("v", "out")), Map.of(), null),
                method("v", "command-virtual", Layer.VIRTUAL, Map.of("in", new Source.Control()), Map.of(),
                        new Expose("v", "127.0.0.1", 7001)),
                method("w", "add-one-virtual", Layer.VIRTUAL, Map.of("in", out("fast", "out")), Map.of(),
                        new Expose("w", "127.0.0.1", 7002))));
        BlockingQueue<Sample> seen = listen(point(g, "w"));
        TestMethods.SlowProcessing slow = (TestMethods.SlowProcessing) g.method("slow");
        ControlPoint v = point(g, "v");
        v.write(v.controlInputs().get(0), new NumberValue(1));
        // The slow method holds its sample until the gate opens; the fast chain answers meanwhile.
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (!slow.busy) {
            assertThat(System.nanoTime()).as("the slow method takes its sample").isLessThan(end);
            Thread.sleep(5);
        }
        Sample s = seen.poll(30, TimeUnit.SECONDS);
        assertThat(s).as("the fast chain's answer while the slow method holds its sample").isNotNull();
        assertThat(s.payload()).isEqualTo(new NumberValue(2));
        assertThat(slow.busy).isTrue();
        slow.gate.countDown();
    }

    @Test
    void aMethodThatThrowsFailsAloneAndTheRestGoesOn() throws Exception {
        MethodGraph g = start(config(-1, 0,
                method("f", "fragile", Layer.PROCESSING, Map.of("in", out("v", "out")), Map.of(), null),
                method("ok", "forward-processing", Layer.PROCESSING, Map.of("in", out("v", "out")), Map.of(), null),
                method("v", "command-virtual", Layer.VIRTUAL, Map.of("in", new Source.Control()), Map.of(),
                        new Expose("v", "127.0.0.1", 7001)),
                method("w", "add-one-virtual", Layer.VIRTUAL, Map.of("in", out("ok", "out")), Map.of(),
                        new Expose("w", "127.0.0.1", 7002))));
        BlockingQueue<Sample> seen = listen(point(g, "w"));
        ControlPoint v = point(g, "v");
        v.write(v.controlInputs().get(0), new NumberValue(-1));
        v.write(v.controlInputs().get(0), new NumberValue(5));
        List<Double> got = new ArrayList<>();
        for (int i = 0; i < 2; i++) {
            got.add(((NumberValue) seen.poll(WAIT_MS, TimeUnit.MILLISECONDS).payload()).value());
        }
        assertThat(got).containsExactly(0.0, 6.0);
        long end = System.nanoTime() + 30_000_000_000L;
        while (!methodStatus(g, "f").path("state").asText().equals("FAILED") && System.nanoTime() < end) {
            Thread.sleep(10);
        }
        assertThat(methodStatus(g, "f").path("state").asText()).isEqualTo("FAILED");
        assertThat(methodStatus(g, "f").path("failure").asText()).contains("negative");
    }

    @Test
    void tickingMethodsTickOnTheEngineClock() throws Exception {
        ManualClock clock = new ManualClock(1_000_000_000L);
        MethodGraph g = MethodGraph.build(config(-1, 0,
                method("t", "ticker", Layer.PROCESSING, Map.of(), Map.of(), null),
                method("w", "add-one-virtual", Layer.VIRTUAL, Map.of("in", out("t", "count")), Map.of(),
                        new Expose("w", "127.0.0.1", 7002))), TestMethods.registry(), clock);
        toClose.add(g);
        BlockingQueue<Sample> seen = listen(point(g, "w"));
        g.start();
        List<Double> got = new ArrayList<>();
        assertThat(seen.poll(100, TimeUnit.MILLISECONDS)).isNull();
        for (int i = 0; i < 3; i++) {
            clock.advanceMillis(100);
            Sample s = seen.poll(WAIT_MS, TimeUnit.MILLISECONDS);
            assertThat(s).isNotNull();
            got.add(((NumberValue) s.payload()).value());
        }
        assertThat(got).containsExactly(2.0, 3.0, 4.0);
        clock.advanceMillis(50);
        assertThat(seen.poll(200, TimeUnit.MILLISECONDS)).isNull();
    }

    @Test
    void theWiresOfADeclaredCycleHoldOnlyTheLatestSampleWhateverTheTypeAsks() {
        MethodConfig a = new MethodConfig("a", "forward-processing", Layer.PROCESSING, Map.of("in", out("b", "out")),
                Map.of(), new NoParams(), Optional.empty(), Optional.empty(), org.habla.config.Fallback.NONE,
                java.util.Set.of("in"));
        MethodGraph g = MethodGraph.build(config(-1, 0, a,
                method("b", "forward-processing", Layer.PROCESSING, Map.of("in", out("a", "out")), Map.of(), null),
                method("off", "forward-processing", Layer.PROCESSING, Map.of("in", out("a", "out")), Map.of(), null)),
                TestMethods.registry(), EngineClock.system());
        toClose.add(g);

        assertThat(methodStatus(g, "a").path("inputs").path("in").path("delivery").asText()).isEqualTo("latest");
        assertThat(methodStatus(g, "b").path("inputs").path("in").path("delivery").asText()).isEqualTo("latest");
        assertThat(methodStatus(g, "off").path("inputs").path("in").path("delivery").asText()).isEqualTo("queue");
    }

    private static JsonNode methodStatus(MethodGraph g, String id) {
        ObjectNode st = g.status();
        for (JsonNode m : st.path("methods")) {
            if (m.path("id").asText().equals(id)) {
                return m;
            }
        }
        throw new AssertionError("no status for " + id + ": " + st);
    }


}
