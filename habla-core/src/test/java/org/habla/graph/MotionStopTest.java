package org.habla.graph;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import org.habla.config.ConfigLoader;
import org.habla.net.Expose;
import org.habla.net.Limits;
import org.habla.method.Input;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.ProcessingMethod;
import org.habla.net.ControlPoint;
import org.habla.net.ControlServer;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.NumberValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The motion watchdog against a robot on loopback, with a control socket in front: who counts as driving the
 * robot, and what reaches the robot after the watchdog stopped it.
 */
@Timeout(60)
class MotionStopTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    /** Passes a number on only when it differs from the last one it passed, as a ramp that is steady does. */
    static final class ChangesOnly extends ProcessingMethod {
        final Output<NumberValue> out = output(TestMethods.OUT);
        final Input<NumberValue> in = input(TestMethods.in(64), this::on);
        private Double last;

        private void on(NumberValue v, Sample s) {
            if (last == null || last != v.value()) {
                last = v.value();
                emit(out, v);
            }
        }

        @Override
        protected void onMotionStopped() {
            last = null;
        }
    }

    /** control → cmd (refuses beyond ±100) → dedupe → act → @robot.motor. The graph alone binds no port. */
    private static final String CONFIG = """
            {"system": "motion-stop-test", "safety": {"watchdogMs": %d}, "status": {"port": 0},
             "interfaces": [{"id": "robot", "driver": "lines-test", "address": "127.0.0.1:%d",
                             "reconnect": {"initialMs": 50, "maxMs": 200}}],
             "methods": [
              {"id": "cmd", "type": "command-virtual", "layer": "virtual", "inputs": {"in": "control"},
               "expose": {"port": 7001, "name": "cmd"}},
              {"id": "dedupe", "type": "%s", "layer": "processing", "inputs": {"in": "cmd.out"}},
              {"id": "act", "type": "forward-actuator", "layer": "sensors_actuators", "inputs": {"in": "dedupe.out"},
               "commands": {"out": "@robot.motor"}}]}
            """;

    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
    }

    private static PluginRegistry registry() {
        PluginRegistry base = TestMethods.registry();
        List<org.habla.plugin.MethodProvider<?>> methods = new ArrayList<>(base.methods().values());
        methods.add(new TestMethods.Simple("changes-only", Layer.PROCESSING, TestMethods.relay(64), ChangesOnly::new));
        methods.add(new TestMethods.Simple("changes-only-light", Layer.PROCESSING, TestMethods.relay(64),
                ChangesOnly::new, true));
        return PluginRegistry.of(methods, List.of(new LineDriver.Provider()));
    }

    private MethodGraph start(FakeLineRobot robot, long watchdogMs) throws Exception {
        return start(robot, watchdogMs, "changes-only");
    }

    /** The graph with {@code dedupeType} between the command and the actuator. */
    private MethodGraph start(FakeLineRobot robot, long watchdogMs, String dedupeType) throws Exception {
        PluginRegistry registry = registry();
        MethodGraph g = MethodGraph.build(new ConfigLoader(registry).parse(CONFIG.formatted(watchdogMs, robot.port(),
                        dedupeType)),
                registry, EngineClock.system());
        toClose.add(g);
        g.start();
        assertThat(robot.awaitClient(5_000)).isTrue();
        awaitLink(g, true);
        return g;
    }

    private static void awaitLink(MethodGraph g, boolean up) throws InterruptedException {
        long end = System.nanoTime() + 5_000_000_000L;
        while (g.status().path("interfaces").get(0).path("up").asBoolean() != up && System.nanoTime() < end) {
            Thread.sleep(5);
        }
        assertThat(g.status().path("interfaces").get(0).path("up").asBoolean()).as("link up").isEqualTo(up);
    }

    private static ControlPoint cmd(MethodGraph g) {
        return g.controlPoints().get(0);
    }

    private static void write(ControlPoint p, double value) throws ControlPoint.Rejected {
        p.write(p.controlInputs().get(0), new NumberValue(value));
    }

    @Test
    void theValueSentLastBeforeATripIsSentAgainWhenWrittenAgain() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot, 0);
        write(cmd(g), 0.5);
        assertThat(robot.next(5_000)).isEqualTo("cmd motor 0.5");
        cmd(g).writerLeft();
        assertThat(robot.next(5_000)).isEqualTo("stop");
        write(cmd(g), 0.5);
        assertThat(robot.next(5_000)).as("the method on the way forgot what it sent before the stop")
                .isEqualTo("cmd motor 0.5");
    }

    @Test
    void aLightMethodOnTheMotionPathRunsOnTheCommandsThreadAndForgetsItsMotionAfterATrip() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot, 0, "changes-only-light");
        JsonNode dedupe = g.status().path("methods").get(1);
        assertThat(dedupe.path("thread").path("inline").asBoolean()).isTrue();
        assertThat(dedupe.path("thread").path("name").asText()).isEqualTo("habla-method-cmd");
        write(cmd(g), 0.5);
        assertThat(robot.next(5_000)).isEqualTo("cmd motor 0.5");
        cmd(g).writerLeft();
        assertThat(robot.next(5_000)).isEqualTo("stop");
        write(cmd(g), 0.5);
        assertThat(robot.next(5_000)).as("the light method forgot what it sent before the stop")
                .isEqualTo("cmd motor 0.5");
    }

    @Test
    void aStopTheWatchdogCouldNotSendIsWrittenBeforeTheNextMotion() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        int port = robot.port();
        MethodGraph g = start(robot, 0);
        write(cmd(g), 0.5);
        assertThat(robot.next(5_000)).isEqualTo("cmd motor 0.5");
        robot.close();
        awaitLink(g, false);
        cmd(g).writerLeft(); // the stop cannot reach the robot now
        FakeLineRobot again = new FakeLineRobot(port);
        toClose.add(again);
        assertThat(again.awaitClient(5_000)).isTrue();
        awaitLink(g, true);
        write(cmd(g), 0.25);
        assertThat(again.next(5_000)).as("the owed stop comes first").isEqualTo("stop");
        assertThat(again.next(5_000)).isEqualTo("cmd motor 0.25");
    }

    @Test
    void aClientWhoseWriteWasRefusedLeavesWithoutStoppingTheRobot() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        MethodGraph g = start(robot, 0);
        ControlServer server = new ControlServer(cmd(g), new Expose("cmd", "127.0.0.1", 0), Limits.DEFAULTS);
        toClose.add(server);
        server.start();
        try (Client driver = new Client(server.port())) {
            try (Client refused = new Client(server.port())) {
                refused.send("{\"value\": 500, \"id\": 1}");
                assertThat(refused.next("error").path("code").asText()).isEqualTo("bad_value");
                driver.send("{\"value\": 0.5, \"id\": 2}");
                driver.next("ok");
                assertThat(robot.next(5_000)).isEqualTo("cmd motor 0.5");
            }
            long end = System.nanoTime() + 5_000_000_000L;
            while (server.clientCount() > 1 && System.nanoTime() < end) {
                Thread.sleep(5);
            }
            assertThat(server.clientCount()).as("the refused client is gone").isEqualTo(1);
            driver.send("{\"value\": 0.25, \"id\": 3}");
            driver.next("ok");
            assertThat(robot.next(5_000)).as("no stop came between").isEqualTo("cmd motor 0.25");
            assertThat(g.status().path("watchdog").path("trips").asLong()).isZero();
        }
    }

    /** A control client over loopback: lines out, JSON lines in, each read within 5 s. */
    private static final class Client implements AutoCloseable {
        private final Socket socket;
        private final BufferedReader in;

        Client(int port) throws IOException {
            socket = new Socket("127.0.0.1", port);
            socket.setSoTimeout(5_000);
            in = new BufferedReader(new InputStreamReader(socket.getInputStream(), UTF_8));
        }

        void send(String line) throws IOException {
            socket.getOutputStream().write((line + "\n").getBytes(UTF_8));
            socket.getOutputStream().flush();
        }

        JsonNode next(String type) throws IOException {
            for (int i = 0; i < 1_000; i++) {
                String line = in.readLine();
                if (line == null) {
                    throw new AssertionError("the socket closed before a '" + type + "' line");
                }
                JsonNode n = JSON.readTree(line);
                if (n.path("type").asText().equals(type)) {
                    return n;
                }
            }
            throw new AssertionError("no '" + type + "' line among 1 000");
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }
}
