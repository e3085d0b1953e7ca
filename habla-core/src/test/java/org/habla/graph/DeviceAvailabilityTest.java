package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import java.util.function.Predicate;
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
import org.habla.net.ControlPoint;
import org.habla.plugin.NoParams;
import org.habla.sample.NumberValue;
import org.habla.testing.LogLines;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * What the status and the log say of the devices behind a link that stays up: which device is offline, which
 * channel it made unavailable, why each method is stale, and why a command was dropped.
 */
@Timeout(60)
class DeviceAvailabilityTest {

    private static final long WAIT_MS = 15_000;

    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
    }

    /** Sensing: @robot.value → s → p → v (exposed). Acting: control → cmd → fwd → act → @robot.motor. */
    private MethodGraph start(int port) {
        MethodConfig s = method("s", "add-one-sensor", Layer.SENSORS_ACTUATORS, new Source.Channel("robot", "value"));
        MethodConfig p = method("p", "add-one-processing", Layer.PROCESSING, new Source.MethodOutput("s", "out"));
        MethodConfig v = new MethodConfig("v", "add-one-virtual", Layer.VIRTUAL,
                Map.of("in", new Source.MethodOutput("p", "out")), Map.of(), new NoParams(),
                Optional.of(new Expose("v", "127.0.0.1", 7001)), Optional.empty());
        MethodConfig cmd = new MethodConfig("cmd", "command-virtual", Layer.VIRTUAL, Map.of("in", new Source.Control()),
                Map.of(), new NoParams(), Optional.of(new Expose("cmd", "127.0.0.1", 7002)), Optional.empty());
        MethodConfig fwd = method("fwd", "forward-processing", Layer.PROCESSING, new Source.MethodOutput("cmd", "out"));
        MethodConfig act = new MethodConfig("act", "forward-actuator", Layer.SENSORS_ACTUATORS,
                Map.of("in", new Source.MethodOutput("fwd", "out")), Map.of("out", new ChannelRef("robot", "motor")),
                new NoParams(), Optional.empty(), Optional.empty());
        InterfaceConfig robot = new InterfaceConfig("robot", "lines-test",
                new InterfaceAddress("127.0.0.1", OptionalInt.of(port)), new NoParams(),
                new Reconnect(50, 200, 1_000, 5_000));
        HablaConfig config = new HablaConfig("device-test", Limits.DEFAULTS, new Safety(0),
                new StatusConfig("127.0.0.1", 0), List.of(robot), List.of(s, p, v, cmd, fwd, act));
        MethodGraph g = MethodGraph.build(config, TestMethods.registry(), EngineClock.system());
        toClose.add(g);
        g.start();
        return g;
    }

    private static MethodConfig method(String id, String type, Layer layer, Source in) {
        return new MethodConfig(id, type, layer, Map.of("in", in), Map.of(), new NoParams(), Optional.empty(),
                Optional.empty());
    }

    private FakeLineRobot robot() throws Exception {
        FakeLineRobot robot = new FakeLineRobot(0);
        toClose.add(robot);
        return robot;
    }

    @Test
    void aStaleMethodSaysWhichChannelAndDeviceMadeItStaleAndTheStatusNamesTheDevice() throws Exception {
        FakeLineRobot robot = robot();
        MethodGraph g = start(robot.port());
        await(g, st -> !method(st, "v").path("stale").asBoolean(), "the link up and v fresh");

        JsonNode st;
        try (LogLines log = new LogLines(InterfaceReadings.class)) {
            robot.send("device hall_sensor offline value");
            st = await(g, x -> method(x, "v").path("stale").asBoolean(), "v stale");
            assertThat(log.at(Level.INFO)).contains("interface robot: device hall_sensor is offline (the robot says "
                    + "offline)");
        }
        for (String id : List.of("s", "p", "v")) {
            JsonNode because = method(st, id).path("staleBecause");
            assertThat(because.path("source").asText()).as(id).isEqualTo("@robot.value");
            assertThat(because.path("why").asText()).as(id).contains("@robot.value", "hall_sensor is offline");
        }
        JsonNode device = st.path("interfaces").get(0).path("devices").path("hall_sensor");
        assertThat(device.path("online").asBoolean(true)).isFalse();
        assertThat(device.path("detail").asText()).isEqualTo("the robot says offline");
        assertThat(method(st, "cmd").has("staleBecause")).as("what does not depend on it is fresh").isFalse();

        robot.send("device hall_sensor online value");
        st = await(g, x -> !method(x, "v").path("stale").asBoolean(), "v fresh again");
        assertThat(method(st, "v").has("staleBecause")).isFalse();
        assertThat(st.path("interfaces").get(0).path("devices").path("hall_sensor").path("online").asBoolean())
                .isTrue();

        robot.close();
        st = await(g, x -> method(x, "v").path("stale").asBoolean(), "v stale with the link down");
        assertThat(method(st, "v").path("staleBecause").path("source").asText()).isEqualTo("@robot");
        assertThat(method(st, "v").path("staleBecause").path("why").asText()).isEqualTo("interface robot is down");
    }

    @Test
    void aCommandTheDeviceRefusesIsDroppedForTheDevicesReasonNotAsALinkDown() throws Exception {
        FakeLineRobot robot = robot();
        MethodGraph g = start(robot.port());
        await(g, st -> st.path("interfaces").get(0).path("up").asBoolean(), "the link up");
        robot.send("device hall_lamp offline motor");
        await(g, st -> st.path("interfaces").get(0).path("devices").has("hall_lamp"), "the lamp reported");
        try (LogLines log = new LogLines(InterfaceCommands.class); LogLines links = new LogLines(ConnectionLink.class)) {
            ControlPoint cmd = g.controlPoints().stream().filter(x -> x.name().equals("cmd")).findFirst().orElseThrow();
            cmd.write(cmd.controlInputs().get(0), new NumberValue(0.5));
            JsonNode st = await(g, x -> x.path("interfaces").get(0).path("commandsDropped").asLong() == 1,
                    "the command dropped");
            JsonNode drop = st.path("interfaces").get(0).path("lastDrop");
            assertThat(drop.path("channel").asText()).isEqualTo("motor");
            assertThat(drop.path("why").asText()).isEqualTo("device hall_lamp is offline");
            assertThat(log.at(Level.WARN)).singleElement().asString()
                    .isEqualTo("interface robot: command on motor dropped (1 dropped so far): device hall_lamp is offline");
            assertThat(links.at(Level.WARN)).as("one warning per drop is enough").isEmpty();
            assertThat(st.path("interfaces").get(0).path("up").asBoolean()).as("the link stays up").isTrue();
        }
    }

    private static JsonNode method(JsonNode status, String id) {
        for (JsonNode m : status.path("methods")) {
            if (m.path("id").asText().equals(id)) {
                return m;
            }
        }
        throw new AssertionError("no method " + id + " in " + status);
    }

    private static JsonNode await(MethodGraph g, Predicate<JsonNode> condition, String what) throws Exception {
        long end = System.nanoTime() + WAIT_MS * 1_000_000L;
        JsonNode st = g.status();
        while (!condition.test(st) && System.nanoTime() < end) {
            Thread.sleep(5);
            st = g.status();
        }
        assertThat(condition.test(st)).as(what + " in " + st).isTrue();
        return st;
    }
}
