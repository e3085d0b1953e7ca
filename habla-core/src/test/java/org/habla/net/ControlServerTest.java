package org.habla.net;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.ImageFrame;
import org.habla.sample.NumberValue;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(60)
class ControlServerTest {

    private static final Limits SMALL = new Limits(4_096, 65_536, 4, 8);

    private final List<AutoCloseable> open = new ArrayList<>();

    private ControlServer serve(FakeControlPoint point, Limits limits) throws IOException {
        ControlServer server = new ControlServer(point, new Expose(point.name(), "127.0.0.1", 0), limits);
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

    @AfterEach
    void closeAll() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
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

    @Test
    void helloDescribesTheMethodItsPortsAndLimits() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        ControlServer server = serve(point, SMALL);
        try (TestClient c = new TestClient(server.port())) {
            ObjectNode hello = c.next().header();
            assertThat(hello.path("protocol").asText()).isEqualTo("habla-control/1");
            assertThat(hello.path("socket").asText()).isEqualTo("tracker");
            assertThat(hello.path("method").asText()).isEqualTo("tracker-method");
            assertThat(hello.path("layer").asText()).isEqualTo("virtual");
            assertThat(hello.path("direction").asText()).isEqualTo("both");
            assertThat(hello.path("outputs").get(3).toString()).isEqualTo("{\"name\":\"value\",\"kind\":\"record\","
                    + "\"unit\":\"\",\"fields\":[\"distanceM\",\"angleRad\",\"visible\"],\"doc\":\"where the object is\"}");
            assertThat(hello.path("outputs").get(0).path("unit").asText()).isEqualTo("m");
            assertThat(hello.path("inputs").toString())
                    .isEqualTo("[{\"name\":\"action\",\"kind\":\"text\"},{\"name\":\"target\",\"kind\":\"vector\"}]");
            assertThat(hello.path("stale").asBoolean(true)).isFalse();
            assertThat(hello.path("limits").toString())
                    .isEqualTo("{\"maxLineBytes\":4096,\"maxBinaryBytes\":65536,\"clientQueueSamples\":8,"
                            + "\"idleTimeoutMs\":300000,\"frameTimeoutMs\":10000}");
        }
        ControlServer readOnly = serve(new FakeControlPoint("reader", false, false), SMALL);
        try (TestClient c = new TestClient(readOnly.port())) {
            assertThat(c.next().header().path("direction").asText()).isEqualTo("out");
        }
    }

    @Test
    void samplesOfEveryKindArriveAsSampleLines() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        ControlServer server = serve(point, SMALL);
        TestClient c = connect(server);
        await("the client is registered", () -> server.clientCount() == 1);
        var values = List.of(new NumberValue(0.75), VectorValue.of(1, 2, 3), new TextValue("left"),
                RecordValue.builder().put("distanceM", 1.25).put("visible", true).build(),
                AudioChunk.of(AudioFormat.MONO_16K, new byte[] {1, 0, 2, 0}),
                ImageFrame.of(1, 1, "gray8", new byte[] {'\n'}));
        var outputs = List.of("distance", "ranges", "command", "value", "audio", "camera");
        for (int i = 0; i < values.size(); i++) {
            point.emit(outputs.get(i), values.get(i));
        }
        for (int i = 0; i < values.size(); i++) {
            Frame f = c.next("sample");
            assertThat(f.header().path("output").asText()).isEqualTo(outputs.get(i));
            assertThat(f.header().path("seq").asLong()).isEqualTo(i + 1);
            assertThat(f.header().path("t").asLong()).isEqualTo(1_000_000L * (i + 1));
            assertThat(SampleCodec.value(f, values.get(i).kind())).isEqualTo(values.get(i));
        }
    }

    @Test
    void writesReachTheControlInputWithTheRightPayload() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        TestClient c = connect(serve(point, SMALL));
        c.send("{\"op\":\"write\",\"input\":\"action\",\"value\":\"forward\",\"id\":1}");
        assertThat(c.next().header().toString()).isEqualTo("{\"type\":\"ok\",\"id\":1}");
        c.send("{\"input\":\"target\",\"value\":[0.5,-1],\"id\":\"b\"}");
        assertThat(c.next().header().toString()).isEqualTo("{\"type\":\"ok\",\"id\":\"b\"}");
        assertThat(point.writes.poll(5, TimeUnit.SECONDS))
                .isEqualTo(new FakeControlPoint.Written("action", new TextValue("forward")));
        assertThat(point.writes.poll(5, TimeUnit.SECONDS))
                .isEqualTo(new FakeControlPoint.Written("target", VectorValue.of(0.5, -1)));

        FakeControlPoint single = new FakeControlPoint("action", true, true);
        TestClient d = connect(serve(single, SMALL));
        d.send("{\"value\":\"back\"}");
        assertThat(single.writes.poll(5, TimeUnit.SECONDS))
                .isEqualTo(new FakeControlPoint.Written("action", new TextValue("back")));
    }

    @Test
    void everyRequestErrorHasItsCodeAndTheConnectionSurvives() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        ControlServer server = serve(point, SMALL);
        TestClient c = connect(server);
        c.send("{\"op\":");
        assertError(c, "bad_json");
        c.sendRaw(new byte[] {'{', '"', (byte) 0xff, '"', ':', '1', '}', '\n'});
        assertError(c, "bad_utf8");
        c.send("[1,2,3]");
        assertError(c, "not_object");
        c.send("{\"pad\":\"" + "z".repeat(5_000) + "\"}");
        assertError(c, "line_too_long");
        c.send("{\"op\":\"write\",\"bytes\":-4}");
        assertError(c, "bad_bytes");
        c.send("{\"op\":\"dance\"}");
        assertError(c, "unknown_op");
        c.send("{\"id\":4}");
        assertThat(assertError(c, "unknown_op").path("id").asInt()).isEqualTo(4);
        c.send("{\"op\":\"write\",\"input\":\"wings\",\"value\":1}");
        assertError(c, "unknown_input");
        c.send("{\"op\":\"write\",\"value\":\"forward\"}");
        assertThat(assertError(c, "unknown_input").path("message").asText()).contains("action", "target");
        c.send("{\"op\":\"write\",\"input\":\"target\",\"value\":\"forward\",\"id\":9}");
        ObjectNode badValue = assertError(c, "bad_value");
        assertThat(badValue.path("message").asText()).contains("expected an array of numbers");
        assertThat(badValue.path("id").asInt()).isEqualTo(9);
        c.send("{\"op\":\"rate\",\"maxHz\":-1}");
        assertError(c, "bad_value");
        point.rejectNext("queue_full", "input action is full");
        c.send("{\"op\":\"write\",\"input\":\"action\",\"value\":\"left\"}");
        assertThat(assertError(c, "queue_full").path("message").asText()).isEqualTo("input action is full");
        point.rejectNext("", "the method failed");
        c.send("{\"op\":\"write\",\"input\":\"action\",\"value\":\"left\"}");
        assertError(c, "rejected");

        c.send("{\"op\":\"ping\",\"id\":\"p\"}");
        assertThat(c.next().header().toString()).isEqualTo("{\"type\":\"pong\",\"id\":\"p\"}");
        assertThat(point.writes).isEmpty();
        assertThat(server.stats().path("errors").asLong()).isEqualTo(13);
        assertThat(server.stats().path("linesIn").asLong()).isEqualTo(9);
    }

    @Test
    void writingToAMethodWithoutControlInputsIsReadOnly() throws Exception {
        FakeControlPoint point = new FakeControlPoint("reader", false, false);
        TestClient c = connect(serve(point, SMALL));
        c.send("{\"op\":\"write\",\"value\":1}");
        assertError(c, "read_only");
    }

    @Test
    void aHugeBytesCountGetsBinaryTooLargeAndTheConnectionCloses() throws Exception {
        ControlServer server = serve(FakeControlPoint.twoWay(), SMALL);
        TestClient c = connect(server);
        c.send("{\"op\":\"write\",\"input\":\"action\",\"kind\":\"text\",\"bytes\":999999999}");
        assertThat(assertError(c, "binary_too_large").path("message").asText()).contains("maxBinaryBytes=65536");
        assertThat(c.next()).isNull();
        await("the client is gone", () -> server.clientCount() == 0);
    }

    @Test
    void latestReturnsTheNewestSampleOfEveryOutput() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        point.emit("distance", new NumberValue(1));
        point.emit("distance", new NumberValue(2));
        point.emit("command", new TextValue("right"));
        TestClient c = connect(serve(point, SMALL));
        c.send("{\"op\":\"latest\",\"id\":7}");
        Frame first = c.next();
        Frame second = c.next();
        assertThat(first.header().path("output").asText()).isEqualTo("distance");
        assertThat(first.header().path("value").asDouble()).isEqualTo(2.0);
        assertThat(second.header().path("value").asText()).isEqualTo("right");
        assertThat(c.next().header().toString()).isEqualTo("{\"type\":\"ok\",\"id\":7}");
    }

    @Test
    void aRateLimitThinsSamplesButTheNewestArrives() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        TestClient c = connect(serve(point, SMALL));
        c.send("{\"op\":\"rate\",\"maxHz\":1,\"id\":1}");
        assertThat(c.next().type()).isEqualTo("ok");
        long last = 0;
        for (int i = 0; i < 200; i++) {
            last = point.emit("distance", new NumberValue(i));
        }
        List<Long> seen = new ArrayList<>();
        while (seen.isEmpty() || seen.getLast() != last) {
            seen.add(c.next("sample").header().path("seq").asLong());
        }
        assertThat(seen).hasSizeLessThanOrEqualTo(3).startsWith(1L).endsWith(last);
    }

    @Test
    void stalenessChangesAreAnnounced() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        ControlServer server = serve(point, SMALL);
        TestClient c = connect(server);
        await("the client is registered", () -> server.clientCount() == 1);
        point.stale(true, "link to pioneer lost");
        assertThat(c.next().header().toString())
                .isEqualTo("{\"type\":\"stale\",\"stale\":true,\"why\":\"link to pioneer lost\"}");
        point.stale(false, "link up");
        assertThat(c.next().header().path("stale").asBoolean(true)).isFalse();
    }

    @Test
    void aClientThatNeverReadsLosesItsOldestSamplesWithoutDelayingAnother() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        ControlServer server = serve(point, SMALL);
        TestClient stalled = connect(server);
        TestClient reader = connect(server);
        await("both clients are registered", () -> server.clientCount() == 2);
        String block = "s".repeat(3_000);
        int count = 4_000;
        for (int i = 1; i <= count; i++) {
            point.emit("command", new TextValue(i + block));
            Frame f = reader.next("sample");
            assertThat(f.header().path("seq").asLong()).isEqualTo(i);
        }
        assertThat(server.stats().path("dropped").asLong()).isPositive();

        long lastSeq = 0;
        Frame dropped = null;
        while (lastSeq != count) {
            Frame f = stalled.next();
            if (f.type().equals("dropped") && dropped == null) {
                dropped = f;
            } else if (f.type().equals("sample")) {
                assertThat(f.header().path("seq").asLong()).isGreaterThan(lastSeq);
                lastSeq = f.header().path("seq").asLong();
            }
        }
        assertThat(dropped).isNotNull();
        assertThat(dropped.header().path("count").asLong()).isPositive();
        assertThat(dropped.header().path("total").asLong()).isGreaterThanOrEqualTo(dropped.header().path("count").asLong());
    }

    @Test
    void aClientWhoseSocketFillsNowAndThenGetsEveryLineWholeWithItsRepliesAmongTheSamples() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        ControlServer server = serve(point, new Limits(4_096, 65_536, 4, 4_096));
        TestClient c = connect(server);
        await("the client is registered", () -> server.clientCount() == 1);
        String block = "b".repeat(2_500);
        int count = 3_000;
        int pings = 0;
        for (int i = 1; i <= count; i++) {
            point.emit("command", new TextValue(i + block)); // lines the socket takes in part once it is full
            if (i % 100 == 0) {
                c.send("{\"op\":\"ping\",\"id\":" + i + "}");
                pings++;
            }
        }
        long lastSeq = 0;
        int pongs = 0;
        while (lastSeq != count) {
            Frame f = c.next(); // fails on a line cut short or spliced into another
            if (f.type().equals("sample")) {
                assertThat(f.header().path("seq").asLong()).isEqualTo(lastSeq + 1); // the queue holds them all
                lastSeq = f.header().path("seq").asLong();
                assertThat(f.header().path("value").asText()).isEqualTo(lastSeq + block);
            } else if (f.type().equals("pong")) {
                pongs++;
            }
        }
        while (pongs < pings) {
            assertThat(c.next().type()).isEqualTo("pong");
            pongs++;
        }
        assertThat(pongs).isEqualTo(pings);
    }

    @Test
    void aNewClientIsRefusedWithAnErrorLineOnlyWhenEveryClientIsWorking() throws Exception {
        ControlServer server = serve(FakeControlPoint.twoWay(), new Limits(4_096, 65_536, 2, 8));
        for (int i = 0; i < 2; i++) {
            TestClient c = connect(server);
            c.send("{\"op\":\"ping\"}");
            c.next("pong");
        }
        try (TestClient third = new TestClient(server.port())) {
            assertThat(third.next().type()).as("a newcomer is let in").isEqualTo("hello");
            third.send("{\"op\":\"ping\"}");
            Frame refused = third.next();
            assertThat(refused.header().path("code").asText()).isEqualTo("too_many_clients");
            assertThat(refused.header().path("message").asText()).contains("maxClientsPerPort=2");
            assertThat(third.next()).isNull();
        }
        assertThat(server.stats().path("refused").asLong()).isEqualTo(1);
    }

    @Test
    void hostileClientsLeaveTheServerServingOthers() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        ControlServer server = serve(point, new Limits(4_096, 65_536, 8, 8));
        TestClient good = connect(server);

        try (TestClient garbage = connect(server)) {
            byte[] noise = new byte[1 << 20];
            new java.util.Random(7).nextBytes(noise);
            garbage.sendRaw(noise);
        }
        try (TestClient longLine = connect(server)) {
            longLine.sendRaw("x".repeat(10 << 20).getBytes(UTF_8));
            longLine.send("");
            assertThat(longLine.next("error").header().path("code").asText()).isEqualTo("line_too_long");
            longLine.send("{\"op\":\"ping\"}");
            assertThat(longLine.next("pong")).isNotNull();
        }
        try (TestClient midBinary = connect(server)) {
            midBinary.send("{\"op\":\"write\",\"input\":\"action\",\"kind\":\"text\",\"bytes\":1000}");
            midBinary.sendRaw(new byte[10]);
        }
        try (TestClient huge = connect(server)) {
            huge.send("{\"bytes\":2147483647}");
            assertThat(huge.next("error").header().path("code").asText()).isEqualTo("binary_too_large");
        }

        await("only the good client is left", () -> server.clientCount() == 1);
        point.emit("distance", new NumberValue(3));
        assertThat(good.next("sample").header().path("value").asDouble()).isEqualTo(3.0);
        good.send("{\"op\":\"ping\"}");
        assertThat(good.next("pong")).isNotNull();
        assertThat(point.writes).isEmpty();
    }

    @Test
    void theEngineHearsWhenTheCommanderLeavesButNotAReadingClient() throws Exception {
        FakeControlPoint point = FakeControlPoint.commanded(0);
        ControlServer server = serve(point, SMALL);
        try (TestClient readerOnly = connect(server)) {
            readerOnly.send("{\"op\":\"ping\"}");
            readerOnly.next("pong");
        }
        try (TestClient writer = connect(server)) {
            writer.send("{\"input\":\"action\",\"value\":\"left\",\"id\":1}");
            writer.next("ok");
        }
        await("both clients are gone", () -> server.clientCount() == 0);
        assertThat(point.writersLeft.get()).isEqualTo(1);
    }

    @Test
    void aTakenPortIsReportedClearly() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            ControlServer server = new ControlServer(FakeControlPoint.twoWay(),
                    new Expose("tracker", "127.0.0.1", taken.getLocalPort()), SMALL);
            assertThatThrownBy(server::start).isInstanceOf(IOException.class)
                    .hasMessageContaining("control socket 'tracker'")
                    .hasMessageContaining("127.0.0.1:" + taken.getLocalPort());
        }
    }

    @Test
    void closingTheServerDisconnectsClientsAndUnsubscribes() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        ControlServer server = serve(point, SMALL);
        TestClient c = connect(server);
        assertThat(point.listenerCount()).isEqualTo(1);
        server.close();
        assertThat(c.next()).isNull();
        assertThat(point.listenerCount()).isZero();
    }

    private static ObjectNode assertError(TestClient c, String code) throws IOException {
        ObjectNode e = c.next().header();
        assertThat(e.path("type").asText()).as(e.toString()).isEqualTo("error");
        assertThat(e.path("code").asText()).as(e.toString()).isEqualTo(code);
        assertThat(e.path("message").asText()).isNotBlank();
        return e;
    }
}
