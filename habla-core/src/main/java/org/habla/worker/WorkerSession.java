// Over 300 lines, on purpose: this is one connection's whole life on the worker (TLS, hello, the daemon's proof,
// the place line, the read loop, the writer with its heartbeat, eviction), and every stage reads and writes the
// same socket, write lock and eviction flag; what the place line makes is PlaceLine's.
package org.habla.worker;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.net.Socket;
import java.util.Optional;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;
import org.habla.net.Limits;
import org.habla.graph.EngineClock;
import org.habla.graph.HostedMethod;
import org.habla.net.BlockBudget;
import org.habla.net.ConnectionGuard;
import org.habla.net.Frame;
import org.habla.net.FrameException;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;
import org.habla.net.PeerActivity;
import org.habla.net.SampleCodec;
import org.habla.net.WorkerProtocol;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.Payload;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One daemon connection to a worker, carrying one placed method (see {@link WorkerProtocol}): says hello,
 * makes the method the daemon asks for, feeds it the samples that arrive and sends back what it publishes.
 * Outgoing lines wait in a bounded queue for one writer thread, which also sends the heartbeat; a full
 * queue drops the newest output sample and counts it. A bad line gets an error line and is skipped.
 * The worker's {@link ConnectionGuard} sees what the connection does and may evict it: the daemon is told why
 * (an error line), then the connection closes.
 */
final class WorkerSession implements Runnable, ConnectionGuard.Guarded {

    private static final Logger LOG = LoggerFactory.getLogger(WorkerSession.class);
    /** How long a new connection may take to say which method to run. */
    static final int PLACE_TIMEOUT_MILLIS = 10_000;
    /** Output lines waiting for the daemon; more are dropped and counted. */
    static final int QUEUE_FRAMES = 256;
    /** How long an evicted connection has to take its error line and close before it is closed anyway. */
    private static final long LINGER_MS = 2_000;

    private volatile Socket socket;
    private final org.habla.security.WorkerSecret secret;
    private final org.habla.security.Tls tls;
    private final AtomicLong authFailures;
    private final org.habla.security.LoginThrottle throttle;
    private final org.habla.net.ClientId id;
    private final PluginRegistry registry;
    private final EngineClock clock;
    private final ExecutorService backgroundPool;
    private final Limits limits;
    private final BlockBudget budget;
    private final ConnectionGuard guard;
    private final ArrayBlockingQueue<Frame> outbound = new ArrayBlockingQueue<>(QUEUE_FRAMES);
    private final AtomicLong dropped = new AtomicLong();
    private final PeerActivity activity = new PeerActivity();
    private final ReentrantLock writeLock = new ReentrantLock();
    private final AtomicBoolean evicted = new AtomicBoolean();
    private volatile boolean open = true;
    private volatile FrameReader frames;
    private volatile FrameWriter out;
    private volatile Thread runner;
    private HostedMethod hosted;
    private String methodId = "?";

    WorkerSession(Socket socket, PluginRegistry registry, EngineClock clock, ExecutorService backgroundPool,
            Limits limits, BlockBudget budget, ConnectionGuard guard, org.habla.security.WorkerSecret secret,
            org.habla.security.Tls tls, AtomicLong authFailures, org.habla.security.LoginThrottle throttle) {
        this.secret = secret;
        this.throttle = throttle;
        this.id = new org.habla.net.ClientId("daemon", "worker", socket.getInetAddress().getHostAddress() + ":"
                + socket.getPort());
        this.tls = tls;
        this.authFailures = authFailures;
        this.socket = socket;
        this.registry = registry;
        this.clock = clock;
        this.backgroundPool = backgroundPool;
        this.limits = limits;
        this.budget = budget;
        this.guard = guard;
    }

    @Override
    public long connectedNanos() {
        return activity.connectedNanos();
    }

    @Override
    public long lastActiveNanos() {
        return activity.lastActiveNanos();
    }

    /** A placed method's heartbeats always wait for the daemon: it is idle when it takes none and sends nothing. */
    @Override
    public long idleSinceNanos() {
        return activity.lastActiveNanos();
    }

    @Override
    public org.habla.net.ClientId id() {
        return id;
    }

    @Override
    public long frameSinceNanos() {
        FrameReader f = frames;
        return f == null ? 0 : f.frameSinceNanos();
    }

    /**
     * Tells the daemon {@code code} and {@code message} (if the line can be written within {@link #LINGER_MS}),
     * ends our side, and closes once the daemon has closed too or after {@link #LINGER_MS}. The method stops.
     */
    @Override
    public void evict(String code, String message) {
        if (!evicted.compareAndSet(false, true)) {
            return;
        }
        LOG.debug("closing the connection of method {} from {}: {}", methodId, socket.getRemoteSocketAddress(), code);
        Thread.ofVirtual().name("habla-worker-evict").start(() -> {
            try {
                FrameWriter w = out;
                if (w != null && writeLock.tryLock(LINGER_MS, TimeUnit.MILLISECONDS)) {
                    try {
                        w.send(WorkerProtocol.error(code, message));
                        socket.shutdownOutput();
                    } finally {
                        writeLock.unlock();
                    }
                    Thread r = runner;
                    if (r != null) {
                        r.join(java.time.Duration.ofMillis(LINGER_MS));
                    }
                }
            } catch (IOException e) {
                LOG.debug("evicting: {}", e.toString());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            open = false;
            try {
                socket.close();
            } catch (IOException e) {
                LOG.debug("evicting: close: {}", e.toString());
            }
        });
    }

    @Override
    public void run() {
        String peer = String.valueOf(socket.getRemoteSocketAddress());
        runner = Thread.currentThread();
        Thread writer = null;
        if (tls != null) {
            try {
                socket = tls.upgrade(socket, (WorkerProtocol.error("tls_required", "this worker speaks TLS only")
                        .toString() + "\n").getBytes(java.nio.charset.StandardCharsets.UTF_8));
            } catch (IOException e) {
                LOG.info("connection from {} refused: {}", peer, e.getMessage());
                open = false;
                return;
            }
        }
        try (Socket socket = this.socket) {
            socket.setTcpNoDelay(true);
            socket.setSoTimeout(PLACE_TIMEOUT_MILLIS);
            FrameReader reader = new FrameReader(new BufferedInputStream(socket.getInputStream(), 65_536),
                    limits.maxLineBytes(), limits.maxBinaryBytes(), budget);
            frames = reader;
            out = new FrameWriter(socket.getOutputStream());
            String challenge = secret == null ? null : org.habla.security.WorkerSecret.challenge();
            send(secret == null ? WorkerProtocol.hello(registry.methods().keySet())
                    : WorkerProtocol.hello(registry.methods().keySet(), challenge));
            if (secret != null && !proven(reader, challenge, peer)) {
                return;
            }
            Frame place = reader.read();
            if (place == null || evicted.get()) {
                return;
            }
            activity.received();
            Optional<String> full = guard.promote(this); // only now does it take a method's place
            if (full.isPresent()) {
                send(WorkerProtocol.error("too_many_methods", full.get()));
                return;
            }
            PlaceLine.Made made = PlaceLine.make(place, registry, clock, backgroundPool);
            methodId = made.methodId();
            if (made.refusal() != null) {
                send(WorkerProtocol.error(made.refusal().code(), made.refusal().message()));
                LOG.warn("refused method {} for {}: {}", methodId, peer, made.refusal().message());
                return;
            }
            hosted = made.hosted();
            send(WorkerProtocol.placed(methodId, hosted.inputNames(), hosted.outputNames()));
            socket.setSoTimeout(0);
            hosted.onOutput((output, sample) -> queue(WorkerProtocol.outputSample(output, sample)));
            hosted.start();
            LOG.info("running method {} for {}", methodId, peer);
            writer = Thread.ofVirtual().name("habla-worker-" + methodId + "-out").start(this::writeLoop);
            readLoop(reader);
        } catch (IOException e) {
            LOG.info("connection of method {} from {} ended: {}", methodId, peer, e.getMessage());
        } catch (RuntimeException e) {
            LOG.warn("connection of method {} from {} failed: {}", methodId, peer, e.toString());
        } finally {
            open = false;
            if (writer != null) {
                writer.interrupt();
            }
            if (hosted != null) {
                hosted.close();
                LOG.info("method {} for {} stopped ({} output samples dropped)", methodId, peer, dropped.get());
            }
        }
    }

    /**
     * Reads the daemon's first line, which must prove the shared secret, while refusing blocks: nothing is buffered
     * for a daemon that has not proved it beyond one line.
     */
    private boolean proven(FrameReader reader, String challenge, String peer) throws IOException {
        reader.refuseBlocks(FrameException.fatal("auth_failed", "no block is read before the shared secret is proved"));
        Frame auth;
        try {
            auth = reader.read();
        } catch (FrameException e) {
            auth = null; // not a line the framing takes (a block, garbage): not a proof
        }
        if (evicted.get()) {
            return false;
        }
        activity.received();
        if (!trusts(auth, challenge, peer)) {
            return false;
        }
        reader.acceptBlocks();
        return true;
    }

    /**
     * Checks the daemon's proof of the shared secret ({@code auth}; null for a line the framing refused) and proves
     * it back; a daemon that does not prove it gets {@code auth_failed} after
     * {@link org.habla.security.PortAccess#FAILURE_DELAY_MS} and no placement, and an address out of tries
     * ({@link org.habla.security.LoginThrottle}) gets {@code auth_throttled} at once, its proof unchecked.
     */
    private boolean trusts(Frame auth, String challenge, String peer) throws IOException {
        long waitMs = throttle.take(id.host());
        if (waitMs > 0) {
            long n = authFailures.incrementAndGet();
            LOG.warn("refused daemon {}: too many failed proofs from its address ({} refused so far)", peer, n);
            send(WorkerProtocol.error("auth_throttled", "too many failed proofs from " + id.host() + ": not checked; "
                    + "try again in " + waitMs + " ms"));
            return false;
        }
        String theirs = auth == null ? null : auth.header().path("challenge").asText(null);
        if (auth != null && auth.type().equals("auth") && theirs != null && theirs.length() <= 256
                && secret.verify(auth.header().path("proof").asText(null), "daemon", challenge, theirs)) {
            throttle.giveBack(id.host());
            send(WorkerProtocol.trusted(secret.proof("worker", challenge, theirs)));
            LOG.info("daemon {} proved the shared secret", peer);
            return true;
        }
        long n = authFailures.incrementAndGet();
        LOG.warn("refused daemon {}: it did not prove the shared secret ({} refused so far)", peer, n);
        try {
            Thread.sleep(org.habla.security.PortAccess.FAILURE_DELAY_MS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        send(WorkerProtocol.error("auth_failed", auth != null && auth.type().equals("auth")
                ? "the proof of the shared secret is wrong: this worker does not trust this daemon"
                : "this worker places methods only for a daemon that proves the shared secret first "
                        + "({\"type\":\"auth\",...}, see docs/protocol.md)"));
        return false;
    }

    /** Writes one line now (before the writer thread runs), taking turns with an eviction's error line. */
    private void send(com.fasterxml.jackson.databind.node.ObjectNode line) throws IOException {
        writeLock.lock();
        try {
            if (!evicted.get()) {
                out.send(line);
                activity.delivered();
            }
        } finally {
            writeLock.unlock();
        }
    }

    private void readLoop(FrameReader reader) throws IOException {
        while (open) {
            Frame f;
            try {
                f = reader.read();
            } catch (FrameException e) {
                if (!evicted.get()) {
                    queue(Frame.of(WorkerProtocol.error(e.code(), e.getMessage())));
                }
                if (e.fatal()) {
                    throw e;
                }
                continue;
            }
            if (f == null) {
                throw new IOException("the daemon closed the connection");
            }
            if (evicted.get()) {
                continue; // read away what the daemon still sends, so our error line is not lost to a reset
            }
            activity.received();
            if (!f.type().equals("sample")) {
                queue(Frame.of(WorkerProtocol.error("unexpected", "a worker takes sample lines, not '" + f.type() + "'")));
                continue;
            }
            try {
                String input = WorkerProtocol.text(f, "input");
                Payload value = SampleCodec.value(f, hosted.inputKind(input));
                ObjectNode h = f.header();
                hosted.offer(input, new Sample(value, "daemon", h.path("seq").asLong(0), h.path("t").asLong(0),
                        h.path("stale").asBoolean(false)));
            } catch (FrameException e) {
                queue(Frame.of(WorkerProtocol.error(e.code(), e.getMessage())));
            } catch (IllegalArgumentException e) {
                queue(Frame.of(WorkerProtocol.error("unknown_input", e.getMessage())));
            }
        }
    }

    private void queue(Frame f) {
        if (!outbound.offer(f)) {
            dropped.incrementAndGet();
        }
    }

    private void writeLoop() {
        long nextBeat = System.nanoTime();
        try {
            while (open && !evicted.get()) {
                long now = System.nanoTime();
                Frame f = null;
                if (now - nextBeat < 0) {
                    f = outbound.poll(Math.max(1, nextBeat - now), TimeUnit.NANOSECONDS);
                }
                writeLock.lock();
                try {
                    if (evicted.get()) {
                        return;
                    }
                    now = System.nanoTime();
                    if (now - nextBeat >= 0) {
                        out.write(WorkerProtocol.heartbeat(hosted.ready(), hosted.readiness()));
                        nextBeat = now + TimeUnit.MILLISECONDS.toNanos(WorkerProtocol.HEARTBEAT_MILLIS);
                    }
                    while (f != null) {
                        out.write(f);
                        f = outbound.poll();
                    }
                    out.flush();
                } finally {
                    writeLock.unlock();
                }
                activity.delivered();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException e) {
            LOG.debug("writing to the daemon failed: {}", e.toString());
            try {
                socket.close();
            } catch (IOException ignored) {
                // the reader notices the closed socket
            }
        }
    }
}
