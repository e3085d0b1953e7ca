package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.config.ConfigLoader;
import org.habla.method.Output;
import org.habla.net.ControlPoint;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Light methods behind one robot connection, run on that connection's reader thread: what they say, where they run,
 * and everything the engine promises of a method — failure kept to the method, staleness, status — kept inline.
 */
@Timeout(60)
class InlineMethodsTest {

    private static final long WAIT_MS = 15_000;
    private static final String READER = "habla-link-robot/main";

    private final List<AutoCloseable> toClose = new ArrayList<>();

    /** A sample a control client would get, and the thread that handed it out. */
    private record Seen(Sample sample, String thread) {
        double value() {
            return ((NumberValue) sample.payload()).value();
        }
    }

    @AfterEach
    void closeAll() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
    }

    private MethodGraph start(FakeLineRobot robot, String methods) throws Exception {
        String json = """
                {"system": "inline-test", "status": {"port": 0},
                 "interfaces": [{"id": "robot", "driver": "lines-test", "address": "127.0.0.1:%d",
                                 "reconnect": {"initialMs": 50, "maxMs": 200}}],
                 "methods": [%s]}
                """.formatted(robot.port(), methods);
        MethodGraph g = MethodGraph.build(new ConfigLoader(TestMethods.registry()).parse(json), TestMethods.registry(),
                EngineClock.system());
        toClose.add(g);
        g.start();
        assertThat(robot.awaitClient(WAIT_MS)).isTrue();
        await(() -> g.status().path("interfaces").get(0).path("up").asBoolean(), "the link is up");
        return g;
    }

    private static final String CHAIN = """
            {"id": "s", "type": "add-one-sensor-light", "layer": "sensors_actuators", "inputs": {"in": "@robot.value"}},
            {"id": "p", "type": "add-one-processing-light", "layer": "processing", "inputs": {"in": "s.out"}},
            {"id": "v", "type": "add-one-virtual-light", "layer": "virtual", "inputs": {"in": "p.out"},
             "expose": {"port": 7001, "name": "v"}}""";

    private static BlockingQueue<Seen> listen(MethodGraph g, String socket) {
        ControlPoint p = g.controlPoints().stream().filter(x -> x.name().equals(socket)).findFirst().orElseThrow();
        BlockingQueue<Seen> q = new LinkedBlockingQueue<>();
        p.subscribe(new ControlPoint.Listener() {
            @Override
            public void onSample(Output<?> output, Sample sample) {
                q.add(new Seen(sample, Thread.currentThread().getName()));
            }

            @Override
            public void onStale(boolean stale, String why) {
            }
        });
        return q;
    }

    private static JsonNode method(MethodGraph g, String id) {
        return method(g.status(), id);
    }

    private static JsonNode method(JsonNode status, String id) {
        for (JsonNode m : status.path("methods")) {
            if (m.path("id").asText().equals(id)) {
                return m;
            }
        }
        throw new AssertionError("no method " + id + " in the status");
    }

    private static boolean threadExists(String name) {
        return Thread.getAllStackTraces().keySet().stream().anyMatch(t -> t.getName().equals(name));
    }

    @Test
    void aLightChainRunsOnTheConnectionsReaderAndSaysSoInItsStatus() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot, CHAIN);
        BlockingQueue<Seen> seen = listen(g, "v");
        for (int i = 1; i <= 3; i++) {
            robot.send("value " + (10 * i));
        }
        List<Seen> got = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            Seen s = seen.poll(WAIT_MS, TimeUnit.MILLISECONDS);
            assertThat(s).isNotNull();
            got.add(s);
        }
        assertThat(got).extracting(Seen::value).containsExactly(13.0, 23.0, 33.0);
        assertThat(got).extracting(Seen::thread).as("the reader hands the last method's sample out").containsOnly(READER);
        JsonNode status = g.status(); // once: each read of the latency starts a new interval
        for (String id : List.of("s", "p", "v")) {
            JsonNode m = method(status, id);
            assertThat(m.path("thread").path("inline").asBoolean()).as(id).isTrue();
            assertThat(m.path("thread").path("name").asText()).as(id).isEqualTo(READER);
            assertThat(m.path("handled").asLong()).as(id + " handled").isEqualTo(3);
            assertThat(m.path("latency").path("count").asLong()).as(id + " latency measured").isEqualTo(3);
            assertThat(m.path("inputs").path("in").path("offered").asLong()).as(id + " offered").isEqualTo(3);
            assertThat(threadExists("habla-method-" + id)).as("a thread of its own for " + id).isFalse();
        }
    }

    @Test
    void aLightMethodThatThrowsFailsAloneAndTheReaderGoesOnWithTheOthers() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot, """
                {"id": "s", "type": "add-one-sensor-light", "layer": "sensors_actuators", "inputs": {"in": "@robot.value"}},
                {"id": "f", "type": "fragile-light", "layer": "processing", "inputs": {"in": "s.out"}},
                {"id": "ok", "type": "forward-processing-light", "layer": "processing", "inputs": {"in": "s.out"}},
                {"id": "v", "type": "add-one-virtual-light", "layer": "virtual", "inputs": {"in": "ok.out"},
                 "expose": {"port": 7001, "name": "v"}}""");
        BlockingQueue<Seen> seen = listen(g, "v");
        robot.send("value -5");
        Seen first = seen.poll(WAIT_MS, TimeUnit.MILLISECONDS);
        assertThat(first).isNotNull();
        assertThat(first.value()).isEqualTo(-3.0);
        assertThat(method(g, "f").path("state").asText()).isEqualTo("FAILED");
        assertThat(method(g, "f").path("failure").asText()).contains("negative");
        robot.send("value 1");
        Seen next = seen.poll(WAIT_MS, TimeUnit.MILLISECONDS);
        assertThat(next).as("the reader lives on and the others still answer").isNotNull();
        assertThat(next.value()).isEqualTo(3.0);
        assertThat(method(g, "ok").path("state").asText()).isEqualTo("RUNNING");
        assertThat(g.status().path("interfaces").get(0).path("up").asBoolean()).isTrue();
    }

    @Test
    void anInlineChainTurnsStaleWhenItsLinkGoesDown() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        MethodGraph g = start(robot, CHAIN);
        ControlPoint v = g.controlPoints().get(0);
        assertThat(v.stale()).isFalse();
        robot.close();
        await(v::stale, "the exposed light method is stale");
        assertThat(method(g, "s").path("stale").asBoolean()).isTrue();
    }

    @Test
    void aLightMethodThatAsksForBackgroundWorkFailsAndSaysWhy() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot, """
                {"id": "s", "type": "add-one-sensor-light", "layer": "sensors_actuators", "inputs": {"in": "@robot.value"}},
                {"id": "b", "type": "background-light", "layer": "processing", "inputs": {"in": "s.out"}}""");
        robot.send("value 1");
        await(() -> method(g, "b").path("state").asText().equals("FAILED"), "the method fails");
        assertThat(method(g, "b").path("failure").asText()).contains("light").contains("background");
    }

    @Test
    void aLightTypeThatAsksForTicksIsRefusedWhenItsMethodIsMade() throws Exception {
        String json = """
                {"system": "inline-test", "status": {"port": 0},
                 "methods": [{"id": "t", "type": "ticker-light", "layer": "processing"}]}""";
        var config = new ConfigLoader(TestMethods.registry()).parse(json);
        MethodNotMadeException e = org.junit.jupiter.api.Assertions.assertThrows(MethodNotMadeException.class,
                () -> MethodGraph.build(config, TestMethods.registry(), EngineClock.system()).close());
        assertThat(e.getMessage()).contains("ticker-light").contains("light").contains("ticks");
    }

    private static void await(BooleanSupplier condition, String what) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
        while (!condition.getAsBoolean()) {
            assertThat(System.nanoTime()).as("waiting until " + what).isLessThan(end);
            Thread.sleep(5);
        }
    }
}
