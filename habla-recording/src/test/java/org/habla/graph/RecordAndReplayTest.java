package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.method.InputPort;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Ports;
import org.habla.method.ProcessingMethod;
import org.habla.method.VirtualMethod;
import org.habla.plugin.PluginRegistry;
import org.habla.recording.RecordedEvent;
import org.habla.recording.Recorder;
import org.habla.recording.Recording;
import org.habla.recording.RecordingHeader;
import org.habla.recording.RecordingReader;
import org.habla.replay.ReplayResult;
import org.habla.replay.Replayer;
import org.habla.replay.StreamMatch;
import org.habla.sample.NumberValue;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A daemon recorded against a robot on loopback, then replayed from the file alone: the exposed methods say
 * the same values in the same order, and the commands the replay would send are the recorded ones.
 */
@Timeout(60)
class RecordAndReplayTest {

    @TempDir
    Path dir;

    static final InputPort<NumberValue> LATEST_IN = InputPort.of("in", NumberValue.class);

    /** Counts its own ticks: what it says depends only on how often the clock ran it. */
    static final class TickCounter extends VirtualMethod {
        final Output<NumberValue> count = output(TestMethods.COUNT);
        private int n;

        TickCounter() {
            tickEvery(Duration.ofMillis(50));
        }

        @Override
        protected void onTick(long nowMicros) {
            emit(count, new NumberValue(++n));
        }
    }

    /** Says the newest value it was given at every tick, as distance-angle does: its output depends on timing. */
    static final class Hold extends VirtualMethod {
        static final OutputPort<NumberValue> HELD = OutputPort.of("held", NumberValue.class);
        final Output<NumberValue> held = output(HELD);
        private double value = Double.NaN;

        Hold() {
            input(LATEST_IN, (v, s) -> value = v.value());
            tickEvery(Duration.ofMillis(20));
        }

        @Override
        protected void onTick(long nowMicros) {
            if (!Double.isNaN(value)) {
                emit(held, new NumberValue(value));
            }
        }
    }

    /**
     * Passes each value on, but holds the first one it takes until the test opens {@link #GATE}: the samples that
     * arrive meanwhile meet a {@code latest} input already full, and all but the newest are skipped, as a busy
     * machine makes a slow method skip them.
     */
    static final class Latched extends ProcessingMethod {
        static volatile CountDownLatch gate = new CountDownLatch(0);
        static volatile boolean holding;
        final Output<NumberValue> out = output(TestMethods.OUT);

        Latched() {
            input(LATEST_IN, (v, s) -> {
                holding = true;
                try {
                    gate.await(60, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                } finally {
                    holding = false;
                }
                emit(out, v);
            });
        }
    }

    private static PluginRegistry registry() {
        PluginRegistry base = TestMethods.registry();
        List<org.habla.plugin.MethodProvider<?>> methods = new ArrayList<>(base.methods().values());
        methods.add(new TestMethods.Simple("tick-counter", Layer.VIRTUAL, Ports.of(TestMethods.COUNT), TickCounter::new));
        methods.add(new TestMethods.Simple("hold", Layer.VIRTUAL, Ports.of(LATEST_IN, Hold.HELD), Hold::new));
        methods.add(new TestMethods.Simple("latched", Layer.PROCESSING, Ports.of(LATEST_IN, TestMethods.OUT), Latched::new));
        return PluginRegistry.of(methods, List.of(new LineDriver.Provider()));
    }

    private static String config(int robotPort) throws java.io.IOException {
        int[] ports = org.habla.testing.DaemonProcess.freePorts(5);
        return """
                {"system": "replay-test", "safety": {"watchdogMs": 0}, "status": {"port": 0},
                 "interfaces": [{"id": "robot", "driver": "lines-test", "address": "127.0.0.1:%d",
                                 "reconnect": {"initialMs": 50, "maxMs": 200}}],
                 "methods": [
                   {"id": "s", "type": "add-one-sensor", "layer": "sensors_actuators", "inputs": {"in": "@robot.value"}},
                   {"id": "p", "type": "add-one-processing", "layer": "processing", "inputs": {"in": "s.out"}},
                   {"id": "v", "type": "add-one-virtual", "layer": "virtual", "inputs": {"in": "p.out"},
                    "expose": {"port": %d, "name": "v"}},
                   {"id": "cmd", "type": "command-virtual", "layer": "virtual", "inputs": {"in": "control"},
                    "expose": {"port": %d, "name": "cmd"}},
                   {"id": "fwd", "type": "forward-processing-light", "layer": "processing", "inputs": {"in": "cmd.out"}},
                   {"id": "act", "type": "forward-actuator", "layer": "sensors_actuators", "inputs": {"in": "fwd.out"},
                    "commands": {"out": "@robot.motor"}},
                   {"id": "ticks", "type": "tick-counter", "layer": "virtual", "expose": {"port": %d, "name": "ticks"}},
                   {"id": "hold", "type": "hold", "layer": "virtual", "inputs": {"in": "p.out"},
                    "expose": {"port": %d, "name": "hold"}},
                   {"id": "ls", "type": "add-one-sensor-light", "layer": "sensors_actuators", "inputs": {"in": "@robot.value"}},
                   {"id": "lp", "type": "add-one-processing-light", "layer": "processing", "inputs": {"in": "ls.out"}},
                   {"id": "lv", "type": "add-one-virtual-light", "layer": "virtual", "inputs": {"in": "lp.out"},
                    "expose": {"port": %d, "name": "lv"}}
                 ]}
                """.formatted(robotPort, ports[0], ports[1], ports[2], ports[3], ports[4]);
    }

    @Test
    void aRecordedRunReplayedAsFastAsPossibleSaysTheSameValuesInTheSameOrder() throws Exception {
        PluginRegistry registry = registry();
        Path file = dir.resolve("run.habla-rec");
        Path configFile = dir.resolve("replay-test.json");
        try (FakeLineRobot robot = new FakeLineRobot(0)) {
            Files.writeString(configFile, config(robot.port()));
            recordLive(file, configFile, registry, robot, daemon -> {
                try (Socket control = new Socket("127.0.0.1", daemon.port("cmd"))) {
                    OutputStream out = control.getOutputStream();
                    for (int i = 1; i <= 40; i++) {
                        robot.send("value " + i);
                        if (i % 4 == 0) {
                            out.write(("{\"value\": " + (i / 100.0) + "}\n").getBytes(StandardCharsets.UTF_8));
                            out.flush();
                            assertThat(robot.next(15_000)).isEqualTo("cmd motor " + (i / 100.0));
                        }
                        Thread.sleep(7);
                    }
                }
                await(() -> outputs(daemon, "v", "out") == 40, "every reading reaches the exposed method");
                await(() -> outputs(daemon, "lv", "out") == 40, "every reading runs through the light chain");
                assertThat(inline(daemon, "lv")).as("the light chain runs on the link's reader").isTrue();
                assertThat(inline(daemon, "fwd")).as("a light method after the control socket's").isTrue();
                // The timed methods ran a few times in the live run, however busy the machine.
                await(() -> outputs(daemon, "ticks", "count") > 3, "the ticker ticks four times");
                await(() -> outputs(daemon, "hold", "held") > 5, "the hold method ticks six times");
            });
        }
        Recording recorded = RecordingReader.readAll(file);
        assertThat(recorded.complete()).isTrue();
        List<Double> v = recorded.events(RecordedEvent.Output.class).stream().filter(o -> o.method().equals("v"))
                .map(o -> ((NumberValue) o.sample().payload()).value()).toList();
        assertThat(v).as("the live run's exposed values").hasSize(40).startsWith(4.0, 5.0, 6.0).endsWith(43.0);

        Replayer replayer = Replayer.open(file, Optional.empty(), registry);
        ReplayResult result = replayer.run(Replayer.Options.AS_FAST_AS_POSSIBLE, Optional.of(dir.resolve("replayed.habla-rec")), d -> { });

        assertThat(recorded.events(RecordedEvent.Reading.class).stream().filter(r -> r.channel().equals("value")))
                .hasSize(40);
        assertThat(result.readings()).as("the robot's readings and the link's records")
                .isEqualTo(recorded.events(RecordedEvent.Reading.class).size());
        assertThat(result.controlWrites()).isEqualTo(10);
        assertThat(result.unsettled()).isZero();
        StreamMatch values = result.stream("v.out").orElseThrow();
        assertThat(values.recorded()).isEqualTo(40);
        assertThat(values.matches()).as(values.toString()).isTrue();
        StreamMatch light = result.stream("lv.out").orElseThrow();
        assertThat(light.recorded()).isEqualTo(40);
        assertThat(light.matches()).as(light.toString()).isTrue();
        StreamMatch echoes = result.stream("cmd.out").orElseThrow();
        assertThat(echoes.recorded()).isEqualTo(10);
        assertThat(echoes.matches()).as(echoes.toString()).isTrue();
        StreamMatch ticks = result.stream("ticks.count").orElseThrow();
        assertThat(ticks.recorded()).as("the ticker ran in the live run").isGreaterThan(3);
        assertThat(ticks.matches()).as(ticks.toString()).isTrue();
        StreamMatch held = result.stream("hold.held").orElseThrow();
        assertThat(held.recorded()).as("the hold method ticked in the live run").isGreaterThan(5);
        assertThat(held.matches()).as(held.toString()).isTrue();
        StreamMatch commands = result.stream("commands").orElseThrow();
        assertThat(commands.recorded()).isEqualTo(10);
        assertThat(commands.matches()).as(commands.toString()).isTrue();
        assertThat(result.cut()).isEmpty();

        ReplayResult paced = replayer.run(new Replayer.Options(8, true, 10_000), Optional.empty(), d -> { });
        assertThat(paced.streams()).as("replayed at 8 times the recorded pace").allMatch(StreamMatch::matches);
    }

    @Test
    void theSamplesASlowMethodSkippedInTheRecordedRunAreSkippedInTheReplay() throws Exception {
        PluginRegistry registry = registry();
        Path file = dir.resolve("skips.habla-rec");
        Path configFile = dir.resolve("skips.json");
        try (FakeLineRobot robot = new FakeLineRobot(0)) {
            int port = org.habla.testing.DaemonProcess.freePorts(1)[0];
            Files.writeString(configFile, """
                    {"system": "skip-test", "safety": {"watchdogMs": 0}, "status": {"port": 0},
                     "interfaces": [{"id": "robot", "driver": "lines-test", "address": "127.0.0.1:%d"}],
                     "methods": [
                       {"id": "s", "type": "add-one-sensor", "layer": "sensors_actuators", "inputs": {"in": "@robot.value"}},
                       {"id": "slow", "type": "latched", "layer": "processing", "inputs": {"in": "s.out"}},
                       {"id": "v", "type": "add-one-virtual", "layer": "virtual", "inputs": {"in": "slow.out"},
                        "expose": {"port": %d, "name": "v"}}
                     ]}
                    """.formatted(robot.port(), port));
            CountDownLatch gate = new CountDownLatch(1);
            Latched.gate = gate;
            try {
                recordLive(file, configFile, registry, robot, daemon -> {
                    robot.send("value 1");
                    await(() -> Latched.holding, "the slow method holds the first value");
                    for (int i = 2; i <= 5; i++) {
                        robot.send("value " + i);
                    }
                    await(() -> conflated(daemon, "slow") == 3, "three values are skipped for a newer one");
                    gate.countDown();
                    await(() -> outputs(daemon, "v", "out") == 2, "the first and the newest value come out");
                    robot.send("value 6");
                    await(() -> outputs(daemon, "v", "out") == 3, "the next value comes out");
                });
            } finally {
                gate.countDown();
                Latched.gate = new CountDownLatch(0);
            }
        }
        Recording recorded = RecordingReader.readAll(file);
        assertThat(recorded.events(RecordedEvent.Skip.class)).filteredOn(k -> k.method().equals("slow"))
                .extracting(RecordedEvent.Skip::arrival).as("the skipped arrivals at slow.in").containsExactly(2L, 3L, 4L);
        List<Double> v = recorded.events(RecordedEvent.Output.class).stream().filter(o -> o.method().equals("v"))
                .map(o -> ((NumberValue) o.sample().payload()).value()).toList();
        assertThat(v).as("values 1, 5 and 6, each plus two").containsExactly(3.0, 7.0, 8.0);

        Path again = dir.resolve("replayed.habla-rec");
        ReplayResult result = Replayer.open(file, Optional.empty(), registry)
                .run(Replayer.Options.AS_FAST_AS_POSSIBLE, Optional.of(again), d -> { });
        StreamMatch values = result.stream("v.out").orElseThrow();
        assertThat(values.replayed()).as(values.toString()).isEqualTo(3);
        assertThat(values.matches()).as(values.toString()).isTrue();
        assertThat(RecordingReader.readAll(again).events(RecordedEvent.Skip.class)).filteredOn(k -> k.method().equals("slow"))
                .as("a recording of the replay says which it skipped too").extracting(RecordedEvent.Skip::arrival)
                .containsExactly(2L, 3L, 4L);
    }

    /** What a live run does while it is recorded to {@code file}. */
    interface LiveRun {
        void run(Daemon daemon) throws Exception;
    }

    /**
     * Starts the daemon of {@code configFile} recording to {@code file}, waits until its link to {@code robot} is up,
     * runs {@code run}, and stops the daemon (the recording then ends).
     */
    private void recordLive(Path file, Path configFile, PluginRegistry registry, FakeLineRobot robot, LiveRun run)
            throws Exception {
        HablaConfig cfg = new ConfigLoader(registry).load(configFile);
        EngineClock clock = EngineClock.system();
        ObjectNode json = (ObjectNode) new ObjectMapper().readTree(Files.readString(configFile));
        try (Recorder recorder = Recorder.create(file, new RecordingHeader(clock.nowMicros(), 1, json,
                dir.toString(), MethodGraph.channels(cfg, registry)), clock);
                Daemon daemon = Daemon.start(cfg, registry, clock, recorder)) {
            assertThat(robot.awaitClient(15_000)).isTrue();
            await(() -> daemon.status().path("interfaces").get(0).path("up").asBoolean(), "the link is up");
            run.run(daemon);
        }
    }

    private static long conflated(Daemon d, String method) {
        for (var m : d.status().path("methods")) {
            if (m.path("id").asText().equals(method)) {
                return m.path("inputs").path("in").path("conflated").asLong();
            }
        }
        return 0;
    }

    private static boolean inline(Daemon d, String method) {
        for (var m : d.status().path("methods")) {
            if (m.path("id").asText().equals(method)) {
                return m.path("thread").path("inline").asBoolean();
            }
        }
        return false;
    }

    private static long outputs(Daemon d, String method, String output) {
        for (var m : d.status().path("methods")) {
            if (m.path("id").asText().equals(method)) {
                return m.path("outputs").path(output).asLong();
            }
        }
        return 0;
    }

    private static void await(java.util.function.BooleanSupplier condition, String what) throws InterruptedException {
        long end = System.nanoTime() + 15_000_000_000L;
        while (!condition.getAsBoolean()) {
            assertThat(System.nanoTime()).as("waiting until " + what).isLessThan(end);
            Thread.sleep(5);
        }
    }
}
