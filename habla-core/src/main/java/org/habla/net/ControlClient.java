// Over 300 lines, on purpose: one client's connection (the reader, the writer, eviction with its lingering error
// line, closing once) shares one socket, outbox and pair of flags; the protocol is ControlProtocol's, the queue
// Outbox's, the hello ControlHello's.
package org.habla.net;

import java.io.IOException;
import java.io.InputStream;
import java.net.SocketTimeoutException;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicBoolean;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One control client's connection: a reader that turns its frames into requests, a writer that drains its
 * {@link Outbox}, each on its own virtual thread. On a plain TCP connection a sample for a client that keeps up
 * (nothing queued, nobody writing) is written by the engine thread that hands it out, without waking the writer;
 * what the socket does not take at once is queued first. Whatever goes wrong stays inside: one log line, the
 * connection closes, the server and the other clients carry on. Its {@link ConnectionGuard} sees what it
 * does ({@link PeerActivity}, the frame it is reading) and may evict it: the client is told why, then closed.
 *
 * <pre>
 *   socket in  -&gt; FrameReader -&gt; ControlProtocol -&gt; ControlPoint.write / replies -+
 *   engine     -&gt; offerSample / offerNotice -----------------------------------&gt; Outbox -&gt; FrameWriter -&gt; socket out
 *   engine     -&gt; offerSample, nothing queued -------------------------------------------&gt; tryWrite --&gt; socket out
 * </pre>
 */
final class ControlClient implements ControlProtocol.Replies, ConnectionGuard.Guarded {

    private static final Logger LOG = LoggerFactory.getLogger(ControlClient.class);
    private static final int REPLY_CAPACITY = 256;
    /** How long a connection that broke the protocol may take to receive its error line before it is closed. */
    private static final long LINGER_MS = 2_000;

    private final ControlConnection socket;
    private final String label;
    private final ControlProtocol protocol;
    private final Limits limits;
    private final BlockBudget budget;
    private final ConnectionGuard guard;
    private final ControlServer.Counters counters;
    private final Runnable onClosed;
    private final Outbox outbox;
    private final PeerActivity activity = new PeerActivity();
    private final AtomicBoolean closed = new AtomicBoolean();
    private final AtomicBoolean evicted = new AtomicBoolean();
    private volatile ClientId id;
    /** Who the client has proved to be; null until then, where the port requires authentication. */
    private volatile org.habla.security.PortAccess.Admitted admitted;
    private volatile Thread writer;
    private volatile Thread reader;
    private volatile FrameReader frames;
    /** Whether the port has made it a client ({@link ConnectionGuard#promote}); read and written by the reader. */
    private boolean promoted;
    /** Whether samples may be written by the engine thread that hands them out ({@link ControlConnection#tryWrite}). */
    private final boolean direct;

    ControlClient(ControlConnection socket, String label, ClientId id, ControlProtocol protocol, Limits limits,
            BlockBudget budget, ConnectionGuard guard, ControlServer.Counters counters, Runnable onClosed) {
        this.socket = socket;
        this.direct = socket.writesWithoutWaiting();
        this.id = id;
        this.label = label;
        this.protocol = protocol;
        this.limits = limits;
        this.budget = budget;
        this.guard = guard;
        this.counters = counters;
        this.onClosed = onClosed;
        this.outbox = new Outbox(limits.clientQueueSamples(), REPLY_CAPACITY);
        this.admitted = protocol.initialAccess();
        try {
            outbox.putReply(EncodedFrame.of(protocol.hello())); // first in the queue, before any sample; never waits when empty
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Starts the reader and the writer. */
    void start() {
        writer = Thread.ofVirtual().name(label + "-writer").start(this::writeLoop);
        reader = Thread.ofVirtual().name(label + "-reader").start(this::readLoop);
    }

    @Override
    public long connectedNanos() {
        return activity.connectedNanos();
    }

    @Override
    public long lastActiveNanos() {
        return activity.lastActiveNanos();
    }

    /**
     * Idle while lines wait that its peer does not take, and, where the port requires authentication, until it has
     * authenticated: it gets nothing to read before, so its silence is not a reader's.
     */
    @Override
    public long idleSinceNanos() {
        if (admitted == null) {
            return activity.connectedNanos();
        }
        long waiting = outbox.waitingSinceNanos();
        return waiting == 0 ? 0 : Math.max(waiting, activity.lastActiveNanos());
    }

    @Override
    public String idleness() {
        return admitted == null ? "it did not authenticate" : "it took nothing of the lines waiting for it and sent nothing";
    }

    @Override
    public long frameSinceNanos() {
        FrameReader f = frames;
        return f == null ? 0 : f.frameSinceNanos();
    }

    /**
     * Sends the client {@code code} and {@code message} instead of anything still queued, ends our side, and
     * closes once the client has closed too or after {@link #LINGER_MS}. What the client sends meanwhile is
     * read and ignored, so the error line is not lost to a reset.
     */
    @Override
    public void evict(String code, String message) {
        if (closed.get() || !evicted.compareAndSet(false, true)) {
            return;
        }
        counters.errors.incrementAndGet();
        outbox.finishWith(EncodedFrame.of(ControlProtocol.error(code, message, null)));
        Thread.ofVirtual().name(label + "-evicted").start(this::lingerThenClose);
    }

    private void lingerThenClose() {
        try {
            Thread w = writer;
            if (w != null && !w.join(java.time.Duration.ofMillis(LINGER_MS))) {
                close();
                return;
            }
            socket.shutdownOutput();
            Thread r = reader;
            if (r != null) {
                r.join(java.time.Duration.ofMillis(LINGER_MS));
            }
        } catch (IOException e) {
            LOG.debug("{}: while evicting: {}", label, e.toString());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        close();
    }

    /**
     * Hands a sample to the client, once it may read (it has authenticated, or the port is open): written at once
     * where the connection allows and nothing is queued, queued otherwise.
     */
    void offerSample(String output, EncodedFrame frame) {
        if (admitted == null) {
            return;
        }
        if (direct && frame.body().length == 0 && outbox.claimDirect()) {
            writeDirect(frame);
            return;
        }
        outbox.offerSample(output, frame);
    }

    /** Writes what the socket takes of {@code frame} now; the rest goes to the outbox, first in line. */
    private void writeDirect(EncodedFrame frame) {
        byte[] line = frame.line();
        int n;
        try {
            n = socket.tryWrite(line);
        } catch (IOException e) {
            n = 0; // the connection is gone: its reader or writer finds out and closes it
        }
        if (n == line.length) {
            outbox.releaseDirect(null, false);
            activity.delivered();
            counters.linesOut.incrementAndGet();
        } else if (n == 0) {
            outbox.releaseDirect(frame, true);
        } else {
            activity.delivered();
            outbox.releaseDirect(new EncodedFrame(frame.frame(), java.util.Arrays.copyOfRange(line, n, line.length)),
                    false);
        }
    }

    void offerNotice(EncodedFrame frame) {
        if (admitted != null) {
            outbox.offerNotice(frame);
        }
    }

    @Override
    public org.habla.security.PortAccess.Admitted admitted() {
        return admitted;
    }

    @Override
    public boolean admit(org.habla.security.PortAccess.Admitted who, com.fasterxml.jackson.databind.JsonNode requestId,
            Frame hello) throws InterruptedException {
        id = id.named(who.principal().name());
        LOG.info("{}: authenticated as client '{}' (role {})", label, who.principal().name(), who.role().fileName());
        if (!becomeClient(requestId)) {
            return false;
        }
        // Admitted as the hello is queued, under the outbox's lock: no sample can overtake the hello, and none emitted
        // once the client could have read the hello is passed over as meant for a client not yet admitted.
        outbox.putReply(EncodedFrame.of(hello), () -> admitted = who);
        FrameReader f = frames;
        if (f != null) {
            f.acceptBlocks();
        }
        return true;
    }

    /**
     * Asks the port for a client's place; without one, the client is told (the port's {@code fullCode}) and closed.
     * Called by the reader when the connection is admitted: its first frame on an open port, its authentication
     * where the port requires it.
     */
    private boolean becomeClient(com.fasterxml.jackson.databind.JsonNode requestId) throws InterruptedException {
        promoted = true;
        Optional<String> refusal = guard.promote(this);
        if (refusal.isEmpty()) {
            return true;
        }
        reply(ControlProtocol.error("too_many_clients", refusal.get(), requestId));
        closeAfterError();
        return false;
    }

    @Override
    public void refuse(Frame error, boolean delay) throws InterruptedException {
        if (delay) {
            Thread.sleep(org.habla.security.PortAccess.FAILURE_DELAY_MS);
        }
        reply(error);
        LOG.info("{}: refused: {}", label, error.header().path("message").asText());
        closeAfterError();
    }

    long dropped() {
        return outbox.droppedTotal();
    }

    @Override
    public void reply(Frame frame) throws InterruptedException {
        if (frame.type().equals("error")) {
            counters.errors.incrementAndGet();
        }
        outbox.putReply(EncodedFrame.of(frame));
    }

    @Override
    public void rate(double maxHz) {
        outbox.rate(maxHz);
    }

    @Override
    public ClientId id() {
        return id;
    }

    private void readLoop() {
        try {
            FrameReader in = new FrameReader(socket.in(), limits.maxLineBytes(), limits.maxBinaryBytes(),
                    budget);
            if (admitted == null) {
                in.refuseBlocks(FrameException.fatal("auth_required", "no block is read before the client has "
                        + "authenticated"));
            }
            frames = in;
            while (!closed.get()) {
                Frame frame;
                try {
                    frame = in.read();
                } catch (FrameException e) {
                    if (evicted.get()) {
                        if (e.fatal()) {
                            break;
                        }
                        continue;
                    }
                    if (admitted == null) { // before authenticating, nothing but an auth line is read
                        refuse(protocol.authRequired(e.code() + ": " + e.getMessage(), null), false);
                        return;
                    }
                    reply(ControlProtocol.error(e.code(), e.getMessage(), null));
                    if (e.fatal()) {
                        LOG.info("{}: closing after a fatal protocol error: {} {}", label, e.code(), e.getMessage());
                        closeAfterError();
                        return;
                    }
                    continue;
                }
                if (frame == null) {
                    break;
                }
                if (evicted.get()) {
                    continue;
                }
                activity.received();
                if (!promoted && admitted != null && !becomeClient(frame.header().get("id"))) {
                    return; // an open port: its first frame makes it a client
                }
                counters.linesIn.incrementAndGet();
                protocol.handle(frame, this);
            }
        } catch (IOException e) {
            if (!closed.get()) {
                LOG.debug("{}: connection lost: {}", label, e.toString());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            LOG.warn("{}: closing after an unexpected error", label, e);
        }
        close();
    }

    private void writeLoop() {
        try {
            FrameWriter out = new FrameWriter(socket.out());
            List<EncodedFrame> batch;
            while ((batch = outbox.take()) != null) {
                out.send(batch);
                outbox.sent();
                activity.delivered();
                counters.linesOut.addAndGet(batch.size());
            }
            return; // the outbox was finished: whoever finished it closes the connection
        } catch (IOException e) {
            if (!closed.get()) {
                LOG.debug("{}: cannot write: {}", label, e.toString());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            LOG.warn("{}: closing after an unexpected error while writing", label, e);
        }
        close();
    }

    /**
     * Lets the writer send what is queued (the error line), ends our side, and reads away what the peer
     * still sends for a moment, so the error is not lost to a reset; then closes.
     */
    private void closeAfterError() {
        outbox.finish();
        try {
            Thread w = writer;
            if (w != null && !w.join(java.time.Duration.ofMillis(LINGER_MS))) {
                close();
                return;
            }
            socket.shutdownOutput();
            socket.readTimeout(200);
            InputStream in = socket.in();
            byte[] sink = new byte[16_384];
            long until = System.nanoTime() + LINGER_MS * 1_000_000;
            while (System.nanoTime() < until && in.read(sink) >= 0) {
                // discard
            }
        } catch (SocketTimeoutException e) {
            // the peer has gone quiet: done
        } catch (IOException e) {
            LOG.debug("{}: while closing: {}", label, e.toString());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        close();
    }

    /** Closes the connection once; if this client commanded the socket, control is free and the robot stopped. */
    void close() {
        if (!closed.compareAndSet(false, true)) {
            return;
        }
        outbox.finish();
        try {
            socket.close();
        } catch (IOException e) {
            LOG.debug("{}: close: {}", label, e.toString());
        }
        try {
            protocol.left(this);
        } catch (RuntimeException e) {
            LOG.warn("{}: the engine failed on the commander leaving", label, e);
        }
        onClosed.run();
        LOG.debug("{}: closed", label);
    }
}
