package org.habla.worker;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import org.habla.net.Limits;
import org.habla.graph.EngineClock;
import org.habla.net.Frame;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;
import org.habla.net.WorkerProtocol;
import org.habla.security.WorkerSecret;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The worker port keeps the control sockets' rules: caps with eviction, deadlines, a budget for blocks. */
@Timeout(60)
class WorkerAvailabilityTest {

    private final List<AutoCloseable> open = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
    }

    private WorkerServer worker(Limits limits) throws IOException {
        return worker(limits, null);
    }

    private WorkerServer worker(Limits limits, WorkerSecret secret) throws IOException {
        EngineClock clock = EngineClock.system();
        WorkerServer w = new WorkerServer(WorkerTestMethods.all(), "127.0.0.1", 0, clock, limits, secret, null);
        open.add(clock::close);
        open.add(w);
        w.start();
        return w;
    }

    /** A daemon's side of one connection, with the real codec and reads that give up after 5 s. */
    private final class Link implements AutoCloseable {
        final Socket socket;
        final FrameReader in;
        final FrameWriter out;

        Link(WorkerServer w) throws IOException {
            this(w, "127.0.0.1");
        }

        /** A link from {@code from} (any 127.x.y.z: each a host of its own). */
        Link(WorkerServer w, String from) throws IOException {
            socket = new Socket();
            socket.bind(new InetSocketAddress(from, 0));
            socket.connect(new InetSocketAddress("127.0.0.1", w.port()), 5_000);
            socket.setSoTimeout(5_000);
            in = new FrameReader(new BufferedInputStream(socket.getInputStream()), 1 << 20, 1 << 20);
            out = new FrameWriter(socket.getOutputStream());
            open.add(this);
        }

        Frame next() throws IOException {
            try {
                return in.read();
            } catch (SocketTimeoutException e) {
                throw new AssertionError("no line from the worker within 5 s", e);
            }
        }

        /** Skips heartbeats (at most 1 000 lines) to the next other line. */
        Frame nextNotHeartbeat() throws IOException {
            for (int i = 0; i < 1_000; i++) {
                Frame f = next();
                if (f == null || !f.type().equals("heartbeat")) {
                    return f;
                }
            }
            throw new AssertionError("only heartbeats");
        }

        Frame place(String id) throws IOException {
            assertThat(next().type()).isEqualTo("hello");
            out.send(WorkerProtocol.place(id, "audio-digest", "processing", JsonNodeFactory.instance.objectNode(),
                    Map.of(), Map.of()));
            return nextNotHeartbeat();
        }

        void sendAudioHeader(int bytes) throws IOException {
            OutputStream o = socket.getOutputStream();
            o.write(("{\"type\":\"sample\",\"input\":\"audio\",\"seq\":1,\"t\":1,\"kind\":\"audio\",\"rateHz\":16000,"
                    + "\"channels\":1,\"bits\":16,\"bytes\":" + bytes + "}\n").getBytes(UTF_8));
            o.flush();
        }

        void sendRaw(byte[] b) throws IOException {
            socket.getOutputStream().write(b);
            socket.getOutputStream().flush();
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }

    private static void await(String what, BooleanSupplier condition) throws InterruptedException {
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > until) {
                throw new AssertionError("timed out waiting until " + what);
            }
            Thread.sleep(5);
        }
    }

    @Test
    void connectionsThatNeverPlaceAMethodCannotKeepADaemonOut() throws Exception {
        WorkerServer w = worker(Limits.DEFAULTS);
        List<Socket> holders = new ArrayList<>();
        try {
            for (int i = 0; i < 70; i++) {
                holders.add(new Socket("127.0.0.1", w.port()));
            }
            await("every holder is let in", () -> w.sessions() >= 70);
            Frame placed = new Link(w).place("digest");
            assertThat(placed.type()).as(placed.header().toString()).isEqualTo("placed");
        } finally {
            for (Socket s : holders) {
                s.close();
            }
        }
    }

    @Test
    void aPlaceLineTrickledByteByByteIsClosedAtTheFrameDeadline() throws Exception {
        WorkerServer w = worker(Limits.DEFAULTS.withDeadlines(60_000, 300, 10_000));
        Link l = new Link(w);
        assertThat(l.next().type()).isEqualTo("hello");
        byte[] line = WorkerProtocol.place("digest", "audio-digest", "processing",
                JsonNodeFactory.instance.objectNode(), Map.of(), Map.of()).toString().getBytes(UTF_8);
        int sent = 0;
        // One byte every 50 ms (the slowloris itself, not a wait); bounded by the line's length.
        while (l.socket.getInputStream().available() == 0 && sent < line.length) {
            l.sendRaw(new byte[] {line[sent++]});
            Thread.sleep(50);
        }
        assertThat(sent).as("closed before the line could be finished").isLessThan(line.length);
        Frame error = l.next();
        assertThat(error.header().path("code").asText()).as(error.header().toString()).isEqualTo("frame_timeout");
        assertThat(error.header().path("message").asText()).contains("limits.frameTimeoutMs=300");
        assertThat(l.next()).isNull();
    }

    @Test
    void placedMethodsAreNotEvictedByAFloodAndAFullWorkerSaysSo() throws Exception {
        WorkerServer w = worker(Limits.DEFAULTS.withCaps(2, 4));
        Link a = new Link(w);
        Link b = new Link(w);
        assertThat(a.place("a").type()).isEqualTo("placed");
        assertThat(b.place("b").type()).isEqualTo("placed");
        List<Socket> flood = new ArrayList<>();
        try {
            for (int i = 0; i < 20; i++) {
                flood.add(new Socket("127.0.0.1", w.port()));
            }
            Frame third = new Link(w).place("c");
            assertThat(third.header().path("code").asText()).as(third.header().toString()).isEqualTo("too_many_methods");
            assertThat(third.header().path("message").asText()).contains("--max-methods=2");
            for (Link l : List.of(a, b)) {
                assertThat(l.next().type()).as("still running").isEqualTo("heartbeat");
            }
        } finally {
            for (Socket s : flood) {
                s.close();
            }
        }
    }

    @Test
    void daemonsThatFailTheSecretNeverCostAGoodDaemonItsPlaceNorHoldABlock() throws Exception {
        WorkerSecret secret = WorkerSecret.of("the-lab-worker-secret-0123");
        WorkerServer w = worker(Limits.DEFAULTS.withCaps(2, 64), secret);
        AtomicBoolean attacking = new AtomicBoolean(true);
        AtomicInteger attempts = new AtomicInteger();
        ExecutorService attackers = Executors.newVirtualThreadPerTaskExecutor();
        try {
            for (int i = 0; i < 20; i++) {
                attackers.submit(() -> {
                    while (attacking.get()) {
                        int n = attempts.incrementAndGet();
                        try (Socket s = new Socket()) { // each attempt from an address of its own
                            s.bind(new InetSocketAddress("127.0." + (1 + n / 250) + "." + (2 + n % 250), 0));
                            s.connect(new InetSocketAddress("127.0.0.1", w.port()), 5_000);
                            s.setSoTimeout(5_000);
                            s.getOutputStream().write((WorkerProtocol.auth("c", "not-the-proof") + "\n").getBytes(UTF_8));
                            s.getInputStream().readAllBytes();
                        } catch (IOException e) {
                            // refused or reset: the next attempt
                        }
                    }
                    return null;
                });
            }
            await("twenty attempts are under way", () -> attempts.get() >= 20);
            for (int i = 0; i < 6; i++) {
                try (Link good = new Link(w)) {
                    WorkerProtocol.Hello hello = WorkerProtocol.Hello.of(good.next());
                    WorkerProtocol.prove(hello, secret, good.in, good.out, "test");
                    good.out.send(WorkerProtocol.place("m" + i, "audio-digest", "processing",
                            JsonNodeFactory.instance.objectNode(), Map.of(), Map.of()));
                    Frame placed = good.nextNotHeartbeat();
                    assertThat(placed.type()).as(placed.header().toString()).isEqualTo("placed");
                }
                // The worker stops a method when its daemon's connection closes, on its session's thread: the next
                // daemon comes once that one has given its place back, so that only the attackers could take it.
                await("the good daemon's method has stopped", () -> w.methodsRunning() == 0);
            }
        } finally {
            attacking.set(false);
            attackers.shutdown();
            assertThat(attackers.awaitTermination(20, TimeUnit.SECONDS)).isTrue();
        }
        Link early = new Link(w);
        assertThat(early.next().type()).isEqualTo("hello");
        early.sendAudioHeader(1 << 20);
        early.sendRaw(new byte[600_000]);
        Frame refused = early.next();
        assertThat(refused.header().path("code").asText()).as(refused.header().toString()).isEqualTo("auth_failed");
        assertThat(w.blockBytesInFlight()).as("nothing is buffered before the daemon proves the secret").isZero();
    }

    @Test
    void aBlockOverTheWorkersBudgetIsRefusedAndItsMemoryComesBack() throws Exception {
        WorkerServer w = worker(new Limits(65_536, 1 << 20, 16, 256).withBlockBudgets(1 << 20, 1 << 20));
        Link holder = new Link(w);
        Link late = new Link(w);
        assertThat(holder.place("a").type()).isEqualTo("placed");
        assertThat(late.place("b").type()).isEqualTo("placed");
        holder.sendAudioHeader(1 << 20);
        holder.sendRaw(new byte[600_000]);
        await("the first block holds the budget", () -> w.blockBytesInFlight() == 1 << 20);
        late.sendAudioHeader(100_000);
        late.sendRaw(new byte[100_000]);
        Frame refused = late.nextNotHeartbeat();
        assertThat(refused.header().path("code").asText()).as(refused.header().toString()).isEqualTo("block_budget");
        assertThat(refused.header().path("message").asText()).contains("limits.socketBlockBudgetBytes=1048576");
        holder.sendRaw(new byte[(1 << 20) - 600_000]);
        Frame digest = holder.nextNotHeartbeat();
        assertThat(digest.header().path("value").asText()).as(digest.header().toString()).startsWith("1048576 ");
        await("the memory is back", () -> w.blockBytesInFlight() == 0);
    }
}
