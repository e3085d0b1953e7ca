package org.habla.net;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.sample.TextValue;
import org.habla.security.AuditEntry;
import org.habla.security.AuditLog;
import org.habla.security.PortAccess;
import org.habla.security.PortSecurity;
import org.habla.testing.LogLines;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Connections that stop taking what they are sent and slow ones are closed on their deadlines, readers stay, a full
 * port still admits a good client, and every eviction is logged and audited.
 */
@Timeout(60)
class ControlSocketAvailabilityTest {

    private final List<AutoCloseable> open = new ArrayList<>();

    /** Small framing limits, {@code cap} clients and pending connections each, and the three deadlines in ms. */
    private static Limits limits(int cap, long idleMs, long frameMs, long evictableMs) {
        return new Limits(4_096, 1 << 20, cap, 64).withCaps(cap, cap).withDeadlines(idleMs, frameMs, evictableMs);
    }

    private ControlServer serve(Limits limits) throws IOException {
        return serve(FakeControlPoint.twoWay(), limits);
    }

    private ControlServer serve(FakeControlPoint point, Limits limits) throws IOException {
        ControlServer server = new ControlServer(point, new Expose("tracker", "127.0.0.1", 0), limits);
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

    private static ObjectNode assertError(TestClient c, String code) throws IOException {
        Frame f = c.next();
        assertThat(f).as("an error line before the end of the stream").isNotNull();
        ObjectNode e = f.header();
        assertThat(e.path("type").asText()).as(e.toString()).isEqualTo("error");
        assertThat(e.path("code").asText()).as(e.toString()).isEqualTo(code);
        return e;
    }

    @Test
    void readersThatSendNothingOutliveTheIdleDeadline() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        // The idle deadline at 200 ms; the witness below is closed at its frame deadline, 1.5 s after it began.
        ControlServer server = serve(point, limits(4, 200, 1_500, 10_000));
        TestClient nc = connect(server); // `nc 127.0.0.1 7002`: never sends a line, takes what comes
        TestClient listener = connect(server); // a control program on a quiet socket: one ping, then it listens
        listener.send("{\"op\":\"ping\"}");
        listener.next("pong");
        TestClient witness = connect(server);
        witness.sendRaw("{\"op\":\"pi".getBytes(UTF_8));
        assertError(witness, "frame_timeout");
        // Both readers have now been quiet (nothing sent, nothing to take) for well over the idle deadline.
        point.emit("command", new TextValue("forward"));
        assertThat(nc.next("sample").header().path("value").asText()).isEqualTo("forward");
        assertThat(listener.next("sample").header().path("value").asText()).isEqualTo("forward");
        assertThat(server.stats().path("idleTimeouts").asLong()).isZero();
    }

    @Test
    void aConnectionThatTakesNothingOfWhatWaitsForItIsClosedAtTheIdleDeadlineAndAReaderStays() throws Exception {
        FakeControlPoint point = FakeControlPoint.twoWay();
        ControlServer server = serve(point, limits(4, 300, 10_000, 10_000));
        TestClient reader = connect(server);
        Socket holder = new Socket();
        open.add(holder);
        holder.setReceiveBufferSize(4_096);
        holder.connect(new InetSocketAddress("127.0.0.1", server.port()));
        await("the holder is admitted", () -> server.clientCount() == 2);
        String big = "x".repeat(100_000);
        // Samples the holder never reads fill its buffers; the reader takes every one. Bounded by the count.
        for (int i = 0; i < 100_000 && server.stats().path("idleTimeouts").asLong() == 0; i++) {
            point.emit("command", new TextValue(big));
            assertThat(reader.next("sample").header().path("value").asText()).hasSize(big.length());
        }
        assertThat(server.stats().path("idleTimeouts").asLong()).isEqualTo(1);
        await("the holder is gone", () -> server.clientCount() == 1);
        point.emit("command", new TextValue("still here"));
        assertThat(reader.next("sample").header().path("value").asText()).isEqualTo("still here");
    }

    @Test
    void everyEvictionAndRefusalIsLoggedAtInfoAndAudited() throws Exception {
        List<AuditEntry> audited = new CopyOnWriteArrayList<>();
        AuditLog audit = AuditLog.withoutFile();
        audit.addListener(audited::add);
        try (LogLines log = new LogLines(ConnectionGuard.class)) {
            ControlServer server = new ControlServer(FakeControlPoint.twoWay(), new Expose("tracker", "127.0.0.1", 0),
                    limits(1, 60_000, 10_000, 60_000), BlockBudget.of("test", 1 << 20),
                    new PortSecurity(PortAccess.open("tracker"), audit, null));
            server.start();
            open.add(server);
            TestClient client = connect(server);
            client.send("{\"op\":\"ping\"}");
            client.next("pong");
            TestClient pending = connect(server);
            TestClient newcomer = connect(server); // the one pending place: the older pending connection gives way
            assertError(pending, "evicted");
            newcomer.send("{\"op\":\"ping\"}"); // the one client place is taken by a working client
            assertError(newcomer, "too_many_clients");
            await("both are audited", () -> audited.size() >= 2);
            assertThat(audited).extracting(e -> e.json().toString()).anySatisfy(e -> assertThat(e)
                    .contains("\"socket\":\"tracker\"", "\"action\":\"connect\"", "\"accepted\":false",
                            "evicted: ", "limits.maxPendingPerPort=1"))
                    .anySatisfy(e -> assertThat(e).contains("\"action\":\"connect\"", "too_many_clients: ",
                            "limits.maxClientsPerPort=1"));
            assertThat(log.at(Level.INFO)).anySatisfy(l -> assertThat(l).contains("evicted", "limits.maxPendingPerPort=1"))
                    .anySatisfy(l -> assertThat(l).contains("too_many_clients", "limits.maxClientsPerPort=1"));
        }
    }

    @Test
    void aFirstLineNeverFinishedIsClosedAtTheFrameDeadline() throws Exception {
        ControlServer server = serve(limits(4, 60_000, 300, 10_000));
        TestClient c = connect(server);
        c.sendRaw("{\"op\":\"pi".getBytes(UTF_8));
        assertThat(assertError(c, "frame_timeout").path("message").asText()).contains("limits.frameTimeoutMs=300");
        assertThat(c.next()).isNull();
    }

    @Test
    void aSlowlorisTricklingALineIsClosedAtTheFrameDeadline() throws Exception {
        ControlServer server = serve(limits(4, 60_000, 300, 10_000));
        TestClient c = connect(server);
        c.send("{\"op\":\"ping\"}");
        c.next("pong");
        byte[] line = "{\"op\":\"write\",\"input\":\"action\",\"value\":\"forward and on and on\"}".getBytes(UTF_8);
        Socket raw = c.socket();
        int sent = 0;
        // One byte every 50 ms (the slowloris itself, not a wait); bounded by the line's length.
        while (raw.getInputStream().available() == 0 && sent < line.length) {
            c.sendRaw(new byte[] {line[sent++]});
            Thread.sleep(50);
        }
        assertThat(sent).as("closed before the line could be finished").isLessThan(line.length);
        assertError(c, "frame_timeout");
        assertThat(server.stats().path("frameTimeouts").asLong()).isEqualTo(1);
    }

    @Test
    void aNewcomerToAPortFullOfSilentConnectionsIsAdmittedAndTheOldestEvicted() throws Exception {
        ControlServer server = serve(limits(2, 60_000, 10_000, 10_000));
        TestClient first = connect(server);
        TestClient second = connect(server);
        await("both holders are registered", () -> server.clientCount() == 2);
        TestClient newcomer = connect(server);
        newcomer.send("{\"op\":\"ping\",\"id\":1}");
        assertThat(newcomer.next("pong")).isNotNull();
        ObjectNode evicted = assertError(first, "evicted");
        assertThat(evicted.path("message").asText()).contains("limits.maxPendingPerPort=2", "no request");
        assertThat(first.next()).isNull();
        second.send("{\"op\":\"ping\",\"id\":2}");
        assertThat(second.next("pong")).isNotNull();
        assertThat(server.stats().path("evicted").asLong()).isEqualTo(1);
        assertThat(server.stats().path("refused").asLong()).isZero();
    }

    @Test
    void aNewClientEvictsAClientThatOnlyHoldsItsPlace() throws Exception {
        ControlServer server = serve(limits(2, 60_000, 10_000, 200));
        TestClient first = connect(server);
        TestClient second = connect(server);
        for (TestClient c : List.of(first, second)) {
            c.send("{\"op\":\"ping\"}");
            c.next("pong");
        }
        TestClient newcomer = connect(server);
        // Both clients are working for 200 ms after their ping: until then the newcomer is refused; then the
        // one idle longest gives way. Each refused newcomer is a fresh connection.
        Frame answer = null;
        for (int i = 0; i < 1_000 && (answer == null || !answer.type().equals("pong")); i++) {
            if (answer != null) {
                assertThat(answer.header().path("code").asText()).isEqualTo("too_many_clients");
                newcomer = connect(server);
            }
            newcomer.send("{\"op\":\"ping\"}");
            answer = newcomer.next();
        }
        assertThat(answer.type()).isEqualTo("pong");
        // One of the two idle clients gave way: the one whose last activity the server stamped first, which on a
        // busy machine need not be the one that pinged first (a writer stamps its delivery after its flush). The
        // evicted one finds the error line; the other answers a new ping.
        List<ObjectNode> heard = new ArrayList<>();
        for (TestClient c : List.of(first, second)) {
            try {
                c.send("{\"op\":\"ping\",\"id\":2}");
            } catch (IOException closedMeanwhile) {
                // the evicted client's connection may already be closed; its error line is still to be read
            }
            heard.add(c.next().header());
        }
        assertThat(heard).extracting(h -> h.path("type").asText()).containsExactlyInAnyOrder("error", "pong");
        ObjectNode evicted = heard.stream().filter(h -> h.path("type").asText().equals("error")).findFirst().orElseThrow();
        assertThat(evicted.path("code").asText()).isEqualTo("evicted");
        assertThat(evicted.path("message").asText()).contains("limits.maxClientsPerPort=2", "limits.evictableIdleMs=200");
    }

    @Test
    void aFloodOfConnectionsNeverEvictsWorkingClientsAndAGoodNewcomerStillGetsIn() throws Exception {
        ControlServer server = serve(limits(4, 60_000, 10_000, 60_000));
        TestClient a = connect(server);
        TestClient b = connect(server);
        for (TestClient c : List.of(a, b)) {
            c.send("{\"op\":\"ping\"}");
            c.next("pong");
        }
        List<Socket> flood = new ArrayList<>();
        try {
            for (int i = 0; i < 300; i++) {
                flood.add(new Socket("127.0.0.1", server.port()));
            }
            TestClient newcomer = connect(server);
            newcomer.send("{\"op\":\"ping\",\"id\":\"new\"}");
            assertThat(newcomer.next("pong").header().path("id").asText()).isEqualTo("new");
            for (TestClient c : List.of(a, b)) {
                c.send("{\"op\":\"ping\",\"id\":\"still\"}");
                assertThat(c.next().header().toString()).isEqualTo("{\"type\":\"pong\",\"id\":\"still\"}");
            }
            await("every flooding connection but the last four evicted",
                    () -> server.stats().path("evicted").asLong() >= 296);
            assertThat(server.stats().path("refused").asLong()).isZero();
        } finally {
            for (Socket s : flood) {
                s.close();
            }
        }
    }

    @Test
    void aBlockOverThePortsBudgetIsRefusedWithTheLimitAndItsMemoryComesBack() throws Exception {
        ControlServer server = serve(new Limits(4_096, 1 << 20, 4, 64).withBlockBudgets(1 << 20, 8 << 20));
        TestClient holder = connect(server);
        TestClient late = connect(server);
        holder.send("{\"op\":\"write\",\"input\":\"action\",\"kind\":\"text\",\"bytes\":1048576,\"id\":1}");
        holder.sendRaw(new byte[600_000]);
        await("the first block holds the port's budget", () -> server.blockBytesInFlight() == 1 << 20);
        late.send("{\"op\":\"write\",\"input\":\"action\",\"kind\":\"text\",\"bytes\":100000,\"id\":2}");
        late.sendRaw(new byte[100_000]);
        ObjectNode refused = assertError(late, "block_budget");
        assertThat(refused.path("message").asText()).contains("limits.socketBlockBudgetBytes=1048576");
        late.send("{\"op\":\"ping\",\"id\":3}");
        assertThat(late.next("pong").header().path("id").asInt()).isEqualTo(3);
        holder.sendRaw(new byte[1_048_576 - 600_000]);
        assertThat(holder.next().header().path("id").asInt()).as("the first block was taken whole").isEqualTo(1);
        await("the memory is back", () -> server.blockBytesInFlight() == 0);
    }

    @Test
    void everyPortOfTheProcessSharesOneBlockBudget() throws Exception {
        BlockBudget process = BlockBudget.of("limits.processBlockBudgetBytes", 1 << 20);
        Limits limits = new Limits(4_096, 1 << 20, 4, 64).withBlockBudgets(1 << 20, 1 << 20);
        ControlServer one = new ControlServer(FakeControlPoint.twoWay(), new Expose("one", "127.0.0.1", 0), limits, process);
        ControlServer two = new ControlServer(FakeControlPoint.twoWay(), new Expose("two", "127.0.0.1", 0), limits, process);
        one.start();
        two.start();
        open.add(one);
        open.add(two);
        TestClient holder = connect(one);
        holder.send("{\"op\":\"write\",\"input\":\"action\",\"kind\":\"text\",\"bytes\":1048576}");
        holder.sendRaw(new byte[600_000]);
        await("the block on port one holds the process's budget", () -> process.reserved() == 1 << 20);
        TestClient other = connect(two);
        other.send("{\"op\":\"write\",\"input\":\"action\",\"kind\":\"text\",\"bytes\":1000}");
        other.sendRaw(new byte[1_000]);
        assertThat(assertError(other, "block_budget").path("message").asText())
                .contains("limits.processBlockBudgetBytes=1048576");
        holder.close();
        await("the memory is back", () -> process.reserved() == 0);
    }
}
