package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.concurrent.BlockingQueue;
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
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.testing.LogLines;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The hardware side of the engine against a robot on loopback: reconnecting, staleness, the watchdog. */
@Timeout(60)
class InterfaceLinkTest {

    /** The bound of every wait for something that must happen: generous, as the suite runs on busy machines. */
    private static final long WAIT_MS = 15_000;

    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
    }

    /** Sensing: @robot.value → s → p → v (exposed). Acting: control → cmd (virtual) → fwd → act → @robot.motor. */
    private MethodGraph start(int port, long watchdogMs) {
        MethodGraph g = build(port, watchdogMs);
        g.start();
        return g;
    }

    private MethodGraph build(int port, long watchdogMs) {
        MethodConfig s = new MethodConfig("s", "add-one-sensor", Layer.SENSORS_ACTUATORS,
                Map.of("in", new Source.Channel("robot", "value")), Map.of(), new NoParams(), Optional.empty(),
                Optional.empty());
        MethodConfig p = new MethodConfig("p", "add-one-processing", Layer.PROCESSING,
                Map.of("in", new Source.MethodOutput("s", "out")), Map.of(), new NoParams(), Optional.empty(),
                Optional.empty());
        MethodConfig v = new MethodConfig("v", "add-one-virtual", Layer.VIRTUAL,
                Map.of("in", new Source.MethodOutput("p", "out")), Map.of(), new NoParams(),
                Optional.of(new Expose("v", "127.0.0.1", 7001)), Optional.empty());
        MethodConfig cmd = new MethodConfig("cmd", "command-virtual", Layer.VIRTUAL,
                Map.of("in", new Source.Control()), Map.of(), new NoParams(),
                Optional.of(new Expose("cmd", "127.0.0.1", 7002)), Optional.empty());
        MethodConfig fwd = new MethodConfig("fwd", "forward-processing", Layer.PROCESSING,
                Map.of("in", new Source.MethodOutput("cmd", "out")), Map.of(), new NoParams(), Optional.empty(),
                Optional.empty());
        MethodConfig act = new MethodConfig("act", "forward-actuator", Layer.SENSORS_ACTUATORS,
                Map.of("in", new Source.MethodOutput("fwd", "out")), Map.of("out", new ChannelRef("robot", "motor")),
                new NoParams(), Optional.empty(), Optional.empty());
        InterfaceConfig robot = new InterfaceConfig("robot", "lines-test",
                new InterfaceAddress("127.0.0.1", OptionalInt.of(port)), new NoParams(),
                new Reconnect(50, 200, 1_000, 5_000));
        HablaConfig config = new HablaConfig("link-test", Limits.DEFAULTS, new Safety(watchdogMs),
                new StatusConfig("127.0.0.1", 0), List.of(robot), List.of(s, p, v, cmd, fwd, act));
        MethodGraph g = MethodGraph.build(config, TestMethods.registry(), EngineClock.system());
        toClose.add(g);
        return g;
    }

    private static ControlPoint point(MethodGraph g, String name) {
        return g.controlPoints().stream().filter(x -> x.name().equals(name)).findFirst().orElseThrow();
    }

    private static final class Recorder implements ControlPoint.Listener {
        final BlockingQueue<Sample> samples = new LinkedBlockingQueue<>();
        final BlockingQueue<Boolean> staleness = new LinkedBlockingQueue<>();

        @Override
        public void onSample(Output<?> output, Sample sample) {
            samples.add(sample);
        }

        @Override
        public void onStale(boolean stale, String why) {
            staleness.add(stale);
        }
    }

    /** The driver's session is up once the link says so, a moment after the robot accepted the connection. */
    private static void awaitUp(MethodGraph g) throws InterruptedException {
        long end = System.nanoTime() + WAIT_MS * 1_000_000L;
        while (!g.status().path("interfaces").get(0).path("up").asBoolean() && System.nanoTime() < end) {
            Thread.sleep(5);
        }
        assertThat(g.status().path("interfaces").get(0).path("up").asBoolean()).as("link up").isTrue();
    }

    /**
     * Waits until the exposed method's staleness is the wanted one: told by a notice, or already so when the
     * change happened before the recorder subscribed.
     */
    private static void awaitStaleness(ControlPoint p, Recorder rec, boolean wanted) throws InterruptedException {
        long end = System.nanoTime() + WAIT_MS * 1_000_000L;
        while (System.nanoTime() < end) {
            Boolean next = rec.staleness.poll(20, TimeUnit.MILLISECONDS);
            if ((next != null && next == wanted) || (next == null && p.stale() == wanted)) {
                return;
            }
        }
        throw new AssertionError("no staleness notice " + wanted + " within " + WAIT_MS + " ms");
    }

    private static void write(ControlPoint p, double value) throws ControlPoint.Rejected {
        p.write(p.controlInputs().get(0), new NumberValue(value));
    }

    @Test
    void anActionWrittenByControlArrivesAtTheRobotAsACommand() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot.port(), 0);
        assertThat(robot.awaitClient(WAIT_MS)).isTrue();
        awaitUp(g);
        write(point(g, "cmd"), 0.25);
        assertThat(robot.next(WAIT_MS)).isEqualTo("cmd motor 0.25");
    }

    @Test
    void aControlValueTheMethodRefusesIsAnsweredAtOnceAndNeverReachesTheRobot() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot.port(), 0);
        assertThat(robot.awaitClient(WAIT_MS)).isTrue();
        awaitUp(g); // a command written while the link is still coming up is dropped, not queued
        ControlPoint.Rejected rejected = org.assertj.core.api.Assertions.catchThrowableOfType(
                ControlPoint.Rejected.class, () -> write(point(g, "cmd"), 500));
        assertThat(rejected).isNotNull();
        assertThat(rejected.code()).isEqualTo("bad_value");
        assertThat(rejected.getMessage()).contains("within ±100");
        write(point(g, "cmd"), 0.75);
        assertThat(robot.next(WAIT_MS)).as("the refused value was never queued").isEqualTo("cmd motor 0.75");
    }

    @Test
    void anActuatorSeesTheCommandChannelItsOutputWrites() {
        MethodGraph g = start(1, 0);
        JsonNode act = null;
        for (JsonNode m : g.status().path("methods")) {
            if (m.path("id").asText().equals("act")) {
                act = m;
            }
        }
        assertThat(act).isNotNull();
        assertThat(act.path("readiness").asText()).isEqualTo("writes motor in m/s");
    }

    @Test
    void theWatchdogStopsTheRobotWhenControlGoesSilentAndDropsLateCommands() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot.port(), 300);
        assertThat(robot.awaitClient(WAIT_MS)).isTrue();
        awaitUp(g);
        long t0 = System.nanoTime();
        write(point(g, "cmd"), 0.5);
        assertThat(robot.next(WAIT_MS)).isEqualTo("cmd motor 0.5");
        assertThat(robot.next(WAIT_MS)).isEqualTo("stop");
        long tookMs = (System.nanoTime() - t0) / 1_000_000;
        assertThat(tookMs).isGreaterThanOrEqualTo(250);
        JsonNode w = g.status().path("watchdog");
        assertThat(w.path("tripped").asBoolean()).isTrue();
        assertThat(w.path("trips").asLong()).isEqualTo(1);
        // A new control value lifts the stop. Written every 100 ms, as a controller does: on a busy machine one
        // write may take longer than the 300 ms watchdog to reach the robot, and then the watchdog stops it again
        // first, rightly; the controller's next write moves it.
        long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WAIT_MS);
        String line = null;
        while (!"cmd motor 0.1".equals(line) && System.nanoTime() < until) {
            write(point(g, "cmd"), 0.1);
            line = robot.next(100);
            assertThat(line).isIn(null, "stop", "cmd motor 0.1");
        }
        assertThat(line).isEqualTo("cmd motor 0.1");
    }

    @Test
    void aDisconnectingDriverStopsTheRobotAtOnce() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot.port(), 0);
        assertThat(robot.awaitClient(WAIT_MS)).isTrue();
        awaitUp(g);
        write(point(g, "cmd"), 0.5);
        assertThat(robot.next(WAIT_MS)).isEqualTo("cmd motor 0.5");
        point(g, "cmd").writerLeft();
        assertThat(robot.next(WAIT_MS)).isEqualTo("stop");
    }

    @Test
    void aRobotKilledAndRestartedIsReconnectedWithStaleThenFreshData() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        int port = robot.port();
        MethodGraph g = start(port, 0);
        Recorder rec = new Recorder();
        point(g, "v").subscribe(rec);
        assertThat(robot.awaitClient(WAIT_MS)).isTrue();
        awaitUp(g);
        awaitStaleness(point(g, "v"), rec, false);
        robot.send("value 1");
        Sample fresh = rec.samples.poll(WAIT_MS, TimeUnit.MILLISECONDS);
        assertThat(fresh.payload()).isEqualTo(new NumberValue(4));
        assertThat(fresh.stale()).isFalse();

        robot.close();
        awaitStaleness(point(g, "v"), rec, true);
        assertThat(point(g, "v").stale()).isTrue();
        // While the robot is away, a motion command is dropped, not queued.
        write(point(g, "cmd"), 0.7);
        long end = System.nanoTime() + WAIT_MS * 1_000_000L;
        while (g.status().path("interfaces").get(0).path("commandsDropped").asLong() == 0 && System.nanoTime() < end) {
            Thread.sleep(10);
        }
        assertThat(g.status().path("interfaces").get(0).path("commandsDropped").asLong()).isEqualTo(1);

        FakeLineRobot again = new FakeLineRobot(port);
        toClose.add(again);
        assertThat(again.awaitClient(WAIT_MS)).isTrue();
        awaitUp(g);
        awaitStaleness(point(g, "v"), rec, false);
        again.send("value 2");
        Sample after = rec.samples.poll(WAIT_MS, TimeUnit.MILLISECONDS);
        assertThat(after.payload()).isEqualTo(new NumberValue(5));
        assertThat(after.stale()).isFalse();
        // The command sent while the robot was away never arrives late.
        assertThat(again.next(300)).isNull();
        JsonNode link = g.status().path("interfaces").get(0);
        assertThat(link.path("connections").get(0).path("connects").asLong()).isEqualTo(2);
    }

    @Test
    void aStandStillCommandDroppedWhileTheLinkIsDownIsCountedWithoutAWarning() throws Exception {
        try (LogLines log = new LogLines(InterfaceCommands.class)) {
            MethodGraph g = start(1, 0);
            write(point(g, "cmd"), 0);
            awaitDropped(g, 1);
            assertThat(log.at(Level.WARN)).as("nothing was lost by dropping a stop").isEmpty();
            write(point(g, "cmd"), 0.5);
            awaitDropped(g, 2);
            assertThat(log.at(Level.WARN)).singleElement().asString()
                    .isEqualTo("interface robot: command on motor dropped (2 dropped so far): link robot/main is down");
        }
    }

    private static void awaitDropped(MethodGraph g, long n) throws InterruptedException {
        long end = System.nanoTime() + 10_000_000_000L;
        while (g.status().path("interfaces").get(0).path("commandsDropped").asLong() < n && System.nanoTime() < end) {
            Thread.sleep(10);
        }
        assertThat(g.status().path("interfaces").get(0).path("commandsDropped").asLong()).isEqualTo(n);
    }

    @Test
    void theLinkRecordOfAChangeGoesOutOnlyOnceTheStalenessItTellsOfIsInForce() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        int port = robot.port();
        MethodGraph g = build(port, 0);
        // Both are told on the link's own thread, in the order the engine does things.
        BlockingQueue<String> events = new LinkedBlockingQueue<>();
        point(g, "v").subscribe(new ControlPoint.Listener() {
            @Override
            public void onSample(Output<?> output, Sample sample) {
            }

            @Override
            public void onStale(boolean stale, String why) {
                events.add("stale " + stale);
            }
        });
        g.interfaceLink("robot").reading("link").subscribe(
                s -> events.add("link " + ((RecordValue) s.payload()).get("up").asBoolean()));
        g.start();
        List<String> seen = new ArrayList<>();
        awaitEvent(events, seen, "link true");
        robot.close();
        awaitEvent(events, seen, "link false");
        FakeLineRobot again = new FakeLineRobot(port);
        toClose.add(again);
        awaitEvent(events, seen, "link true");

        boolean linkUp = false;
        boolean stale = true;
        for (String e : seen) {
            if (e.startsWith("stale ")) {
                stale = e.equals("stale true");
            } else if (e.equals("link " + !linkUp)) {
                linkUp = !linkUp;
                assertThat(stale).as("stale when the record saying up=%s went out (events %s)", linkUp, seen)
                        .isEqualTo(!linkUp);
            }
        }
    }

    private static void awaitEvent(BlockingQueue<String> events, List<String> seen, String wanted)
            throws InterruptedException {
        long end = System.nanoTime() + 10_000_000_000L;
        while (System.nanoTime() < end) {
            String e = events.poll(50, TimeUnit.MILLISECONDS);
            if (e != null) {
                seen.add(e);
                if (e.equals(wanted)) {
                    return;
                }
            }
        }
        throw new AssertionError("no '" + wanted + "' within 10 s; saw " + seen);
    }

    @Test
    void malformedReadingsAreCountedAndTheLinkStaysUp() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot.port(), 0);
        Recorder rec = new Recorder();
        point(g, "v").subscribe(rec);
        assertThat(robot.awaitClient(WAIT_MS)).isTrue();
        awaitUp(g);
        robot.send("value not-a-number");
        robot.send("nosuchchannel 3");
        robot.send("value 7");
        assertThat(rec.samples.poll(WAIT_MS, TimeUnit.MILLISECONDS).payload()).isEqualTo(new NumberValue(10));
        JsonNode link = g.status().path("interfaces").get(0);
        assertThat(link.path("malformed").asLong()).isEqualTo(1);
        assertThat(link.path("unknownChannel").asLong()).isEqualTo(1);
        assertThat(link.path("up").asBoolean()).isTrue();
    }
}
