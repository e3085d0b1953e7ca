package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.sample.TextValue;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** One commander at a time on a socket whose values reach an actuator. */
@Timeout(60)
class ControlLeaseTest {

    private final List<AutoCloseable> open = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
    }

    private ControlServer serve(FakeControlPoint point) throws IOException {
        ControlServer server = new ControlServer(point, new Expose(point.name(), "127.0.0.1", 0), Limits.DEFAULTS);
        server.start();
        open.add(server);
        return server;
    }

    private TestClient connect(ControlServer server) throws IOException {
        TestClient c = new TestClient(server.port());
        open.add(c);
        assertThat(c.next().type()).isEqualTo("hello");
        return c;
    }

    private static void await(String what, BooleanSupplier condition) throws InterruptedException {
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > until) {
                throw new AssertionError("timed out waiting until " + what);
            }
            Thread.sleep(5);
        }
    }

    private static JsonNode write(TestClient c, String label, int id) throws IOException {
        c.send("{\"input\":\"action\",\"value\":\"" + label + "\",\"id\":" + id + "}");
        for (int i = 0; i < 100; i++) {
            JsonNode n = c.next().header();
            if (n.path("id").asInt(-1) == id) {
                return n;
            }
        }
        throw new AssertionError("no answer to request " + id);
    }

    @Test
    void aSecondClientWritingWhileAnotherCommandsIsToldWhoCommandsAndSinceWhen() throws Exception {
        FakeControlPoint point = FakeControlPoint.commanded(0);
        ControlServer server = serve(point);
        TestClient first = connect(server);
        TestClient second = connect(server);
        assertThat(write(first, "forward", 1).path("type").asText()).isEqualTo("ok");
        JsonNode busy = write(second, "back", 2);
        assertThat(busy.path("type").asText()).isEqualTo("error");
        assertThat(busy.path("code").asText()).isEqualTo("busy");
        assertThat(busy.path("message").asText()).contains("commanded by tracker#1 (127.0.0.1:", " since 20",
                "{\"op\":\"take\"}");
        assertThat(point.writes).extracting(w -> ((TextValue) w.value()).text()).containsExactly("forward");
    }

    @Test
    void takingControlIsToldToEveryClientAndTheOldCommanderLeavesWithoutStoppingTheRobot() throws Exception {
        FakeControlPoint point = FakeControlPoint.commanded(0);
        ControlServer server = serve(point);
        TestClient first = connect(server);
        TestClient second = connect(server);
        write(first, "forward", 1); // its first write makes it the commander (a control line before the ok)
        second.send("{\"op\":\"take\",\"id\":5}");
        assertThat(second.next("ok").header().path("id").asInt()).isEqualTo(5);
        JsonNode told = first.next("control").header();
        assertThat(told.path("holder").path("connection").asText()).isEqualTo("tracker#2");
        assertThat(told.path("why").asText()).contains("taken from tracker#1");
        assertThat(write(first, "left", 2).path("code").asText()).isEqualTo("busy");
        assertThat(write(second, "right", 3).path("type").asText()).isEqualTo("ok");
        first.close();
        await("the old commander is gone", () -> server.clientCount() == 1);
        assertThat(point.writersLeft.get()).as("it no longer commanded").isZero();
        second.close();
        await("the commander is gone", () -> server.clientCount() == 0);
        assertThat(point.writersLeft.get()).as("the commander's leaving stops the robot").isEqualTo(1);
    }

    @Test
    void releasingControlStopsTheRobotAndFreesTheSocket() throws Exception {
        FakeControlPoint point = FakeControlPoint.commanded(0);
        ControlServer server = serve(point);
        TestClient first = connect(server);
        TestClient second = connect(server);
        write(first, "forward", 1);
        first.send("{\"op\":\"release\",\"id\":2}");
        first.next("ok");
        assertThat(point.writersLeft.get()).isEqualTo(1);
        assertThat(server.stats().path("control").path("holder").isNull()).isTrue();
        assertThat(write(second, "back", 3).path("type").asText()).isEqualTo("ok");
        first.send("{\"op\":\"release\",\"id\":4}");
        assertThat(first.next("error").header().path("code").asText()).isEqualTo("not_commander");
    }

    @Test
    void aRefusedWriteDoesNotMakeItsClientTheCommander() throws Exception {
        FakeControlPoint point = FakeControlPoint.commanded(0);
        ControlServer server = serve(point);
        TestClient refused = connect(server);
        TestClient driver = connect(server);
        point.rejectNext("bad_value", "unknown action 'jump'");
        assertThat(write(refused, "jump", 1).path("code").asText()).isEqualTo("bad_value");
        assertThat(write(driver, "forward", 2).path("type").asText()).isEqualTo("ok");
        refused.close();
        await("the refused client is gone", () -> server.clientCount() == 1);
        assertThat(point.writersLeft.get()).isZero();
    }

    @Test
    void aCommanderSilentLongerThanTheLapseTimeLosesControlToTheNextClientThatWrites() throws Exception {
        FakeControlPoint point = FakeControlPoint.commanded(200);
        ControlServer server = serve(point);
        TestClient first = connect(server);
        TestClient second = connect(server);
        write(first, "forward", 1);
        String answer = write(second, "back", 2).path("code").asText("ok");
        for (int id = 3; answer.equals("busy") && id < 1_000; id++) {
            Thread.sleep(20);
            answer = write(second, "back", id).path("code").asText("ok");
        }
        assertThat(answer).isEqualTo("ok");
        JsonNode told = first.next("control").header(); // its own first write
        if (told.path("holder").path("connection").asText().equals("tracker#1")) {
            told = first.next("control").header();
        }
        assertThat(told.path("holder").path("connection").asText()).isEqualTo("tracker#2");
        assertThat(told.path("why").asText()).contains("tracker#1", "was silent for");
    }

    @Test
    void aClientWithAHoldOfItsOwnLosesControlAfterItEvenOnASocketWhoseControlNeverLapses() throws Exception {
        long[] nowMicros = {1_000_000};
        List<Frame> told = new ArrayList<>();
        int[] stops = {0};
        ControlLease lease = new ControlLease("action", 0, () -> nowMicros[0], () -> stops[0]++, told::add);
        ClientId bridgeId = new ClientId("mqtt-bridge", "127.0.0.1:1883");
        ControlLease.Client bridge = new ControlLease.Client() {
            @Override
            public ClientId id() {
                return bridgeId;
            }

            @Override
            public long holdMillis() {
                return 500;
            }
        };
        ClientId socketId = new ClientId("action#1", "127.0.0.1:50000");
        ControlLease.Client socketClient = () -> socketId;
        lease.write(bridge, () -> { });
        nowMicros[0] += 400_000;
        try {
            lease.write(socketClient, () -> { });
            throw new AssertionError("the socket client wrote while the bridge held control");
        } catch (ControlPoint.Rejected e) {
            assertThat(e.code()).isEqualTo("busy");
        }
        assertThat(lease.status().path("holder").path("connection").asText()).isEqualTo("mqtt-bridge");
        nowMicros[0] += 200_000;
        assertThat(lease.status().path("holder").isNull()).as("a lapsed hold shows nobody").isTrue();
        lease.write(socketClient, () -> { });
        assertThat(told.getLast().header().path("holder").path("connection").asText()).isEqualTo("action#1");
        // The socket client has no hold of its own: on this socket it keeps control however long it is silent.
        nowMicros[0] += 3_600_000_000L;
        try {
            lease.write(bridge, () -> { });
            throw new AssertionError("the bridge wrote while the socket client held control");
        } catch (ControlPoint.Rejected e) {
            assertThat(e.code()).isEqualTo("busy");
        }
        assertThat(stops[0]).isZero();
    }

    @Test
    void theHelloAndTheStatusShowWhoCommands() throws Exception {
        FakeControlPoint point = FakeControlPoint.commanded(0);
        ControlServer server = serve(point);
        TestClient first = connect(server);
        assertThat(server.stats().path("control").path("holder").isNull()).isTrue();
        write(first, "forward", 1);
        JsonNode control = server.stats().path("control");
        assertThat(control.path("holder").path("connection").asText()).isEqualTo("tracker#1");
        assertThat(control.path("holder").path("address").asText()).startsWith("127.0.0.1:");
        assertThat(control.path("since").asText()).endsWith("Z");
        try (TestClient late = new TestClient(server.port())) {
            JsonNode hello = late.next().header();
            assertThat(hello.path("control").path("holder").path("connection").asText()).isEqualTo("tracker#1");
        }
    }

    @Test
    void aNoticeFromAMethodTheValuesReachGoesToEveryClientWithTheTimeOfTheWrite() throws Exception {
        FakeControlPoint point = FakeControlPoint.commanded(0);
        ControlServer server = serve(point);
        TestClient first = connect(server);
        TestClient second = connect(server);
        await("both clients are in", () -> server.clientCount() == 2);
        point.notice(new org.habla.method.ControlNotice("veto", "safety",
                "forward motion vetoed: obstacle 0.20 m ahead (stop distance 0.25 m)",
                org.habla.sample.RecordValue.builder().put("reason", "obstacle_ahead").put("stopDistanceM", 0.25).build(),
                1_700_000_000_123_456L));
        for (TestClient c : List.of(first, second)) {
            JsonNode n = c.next("notice").header();
            assertThat(n.path("notice").asText()).isEqualTo("veto");
            assertThat(n.path("method").asText()).isEqualTo("safety");
            assertThat(n.path("t").asLong()).isEqualTo(1_700_000_000_123_456L);
            assertThat(n.path("message").asText()).contains("stop distance 0.25 m");
            assertThat(n.path("detail").path("reason").asText()).isEqualTo("obstacle_ahead");
        }
    }

    @Test
    void aSocketWhoseValuesMoveNothingHasNoControlToTake() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        ControlServer server = serve(point);
        TestClient first = connect(server);
        TestClient second = connect(server);
        assertThat(write(first, "forward", 1).path("type").asText()).isEqualTo("ok");
        assertThat(write(second, "back", 2).path("type").asText()).isEqualTo("ok");
        second.send("{\"op\":\"take\",\"id\":3}");
        assertThat(second.next("error").header().path("code").asText()).isEqualTo("no_control");
        assertThat(server.stats().has("control")).isFalse();
    }
}
