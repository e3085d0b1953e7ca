package org.habla.net;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import org.habla.config.Expose;
import org.habla.config.Limits;
import org.habla.method.Output;
import org.habla.sample.Sample;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The TCP server of one exposed method: every client gets the method's hello, its samples as they come,
 * and may write values to its control inputs (protocol {@code habla-control/1}, see {@link ControlProtocol}
 * and {@code docs/protocol.md}).
 *
 * <pre>
 *   engine --samples, staleness--&gt; listener (encodes once, only enqueues) --&gt; client 1 outbox --&gt; writer
 *                                                                       \--&gt; client 2 outbox --&gt; writer
 *   acceptor thread --&gt; ControlClient per connection (virtual threads), at most maxClientsPerPort
 * </pre>
 *
 * The engine's listener never blocks and never does I/O; a client that stops reading loses its oldest
 * samples (counted, and told) and delays nobody else.
 */
public final class ControlServer implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(ControlServer.class);

    private final ControlPoint point;
    private final Expose expose;
    private final Limits limits;
    private final ControlProtocol protocol;
    private final List<ControlClient> clients = new CopyOnWriteArrayList<>();
    private final Counters counters = new Counters();
    private final AtomicLong droppedByGone = new AtomicLong();
    /**
     * The longest {@link #close} waits for the acceptor to leave its {@code accept}: the operating system releases
     * the port only then, so a daemon started right after this one closed can have it.
     */
    static final long ACCEPTOR_STOP_MILLIS = 2_000;

    private volatile ServerSocket listener;
    private volatile Thread acceptor;
    private volatile ControlPoint.Subscription subscription;
    private volatile boolean closed;

    /** The server's running counts. */
    static final class Counters {
        final AtomicLong connections = new AtomicLong();
        final AtomicLong refused = new AtomicLong();
        final AtomicLong linesIn = new AtomicLong();
        final AtomicLong linesOut = new AtomicLong();
        final AtomicLong errors = new AtomicLong();
    }

    public ControlServer(ControlPoint point, Expose expose, Limits limits) {
        this.point = Objects.requireNonNull(point, "point");
        this.expose = Objects.requireNonNull(expose, "expose");
        this.limits = Objects.requireNonNull(limits, "limits");
        this.protocol = new ControlProtocol(point, limits);
    }

    /**
     * Binds the port without accepting anyone yet, so a daemon can hold all its ports before it serves on any.
     * A connection that arrives before {@link #start} waits in the backlog (and is reset if the server closes).
     */
    public void bind() throws IOException {
        if (listener != null) {
            throw new IllegalStateException("control socket '" + point.name() + "' is already bound");
        }
        String bind = bindAddress();
        ServerSocket server = new ServerSocket();
        try {
            server.setReuseAddress(true);
            server.bind(new InetSocketAddress(InetAddress.getByName(bind), expose.port()), 50);
        } catch (IOException e) {
            server.close();
            throw new IOException("control socket '" + point.name() + "' of method " + point.methodId()
                    + " cannot listen on " + bind + ":" + expose.port() + ": " + e.getMessage(), e);
        }
        listener = server;
    }

    /** Binds the port if {@link #bind} was not called, and starts accepting clients. */
    public void start() throws IOException {
        if (subscription != null) {
            throw new IllegalStateException("control socket '" + point.name() + "' is already started");
        }
        if (listener == null) {
            bind();
        }
        String bind = bindAddress();
        subscription = point.subscribe(new Fanout());
        Thread a = new Thread(this::acceptLoop, "control-" + point.name() + "-accept");
        a.setDaemon(true);
        acceptor = a;
        a.start();
        LOG.info("control socket '{}' of method {} listening on {}:{}", point.name(), point.methodId(), bind, port());
    }

    private String bindAddress() {
        return expose.bind() == null || expose.bind().isBlank() ? "127.0.0.1" : expose.bind();
    }

    /** The bound port (useful when the config asked for port 0). */
    public int port() {
        ServerSocket s = listener;
        if (s == null) {
            throw new IllegalStateException("control socket '" + point.name() + "' is not started");
        }
        return s.getLocalPort();
    }

    public int clientCount() {
        return clients.size();
    }

    /** Clients now and in total, refused connections, lines each way, dropped samples and protocol errors. */
    public ObjectNode stats() {
        long dropped = droppedByGone.get();
        for (ControlClient c : clients) {
            dropped += c.dropped();
        }
        return JsonNodeFactory.instance.objectNode()
                .put("socket", point.name())
                .put("port", listener == null ? expose.port() : port())
                .put("clients", clients.size())
                .put("connections", counters.connections.get())
                .put("refused", counters.refused.get())
                .put("linesIn", counters.linesIn.get())
                .put("linesOut", counters.linesOut.get())
                .put("dropped", dropped)
                .put("errors", counters.errors.get());
    }

    @Override
    public void close() {
        closed = true;
        ControlPoint.Subscription s = subscription;
        if (s != null) {
            s.close();
        }
        ServerSocket l = listener;
        if (l != null) {
            try {
                l.close();
            } catch (IOException e) {
                LOG.debug("closing control socket '{}': {}", point.name(), e.toString());
            }
        }
        awaitAcceptorGone();
        for (ControlClient c : clients) {
            c.close();
        }
    }

    private void awaitAcceptorGone() {
        Thread a = acceptor;
        if (a == null || a == Thread.currentThread()) {
            return;
        }
        try {
            a.join(ACCEPTOR_STOP_MILLIS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void acceptLoop() {
        long n = 0;
        while (!closed) {
            Socket socket;
            try {
                socket = listener.accept();
            } catch (IOException e) {
                if (!closed) {
                    LOG.warn("control socket '{}' stopped accepting: {}", point.name(), e.toString());
                }
                return;
            }
            try {
                admit(socket, ++n);
            } catch (IOException | RuntimeException e) {
                LOG.warn("control socket '{}': could not admit {}: {}", point.name(),
                        socket.getRemoteSocketAddress(), e.toString());
                closeQuietly(socket);
            }
        }
    }

    private void admit(Socket socket, long n) throws IOException {
        socket.setTcpNoDelay(true);
        if (clients.size() >= limits.maxClientsPerPort()) {
            counters.refused.incrementAndGet();
            LOG.warn("control socket '{}': refusing {}: {} clients already", point.name(),
                    socket.getRemoteSocketAddress(), clients.size());
            socket.setSoTimeout(1_000);
            OutputStream out = socket.getOutputStream();
            new FrameWriter(out).send(ControlProtocol.error("too_many_clients", "socket '" + point.name()
                    + "' already has maxClientsPerPort=" + limits.maxClientsPerPort() + " clients", null).header());
            socket.shutdownOutput();
            closeQuietly(socket);
            return;
        }
        counters.connections.incrementAndGet();
        String label = "control-" + point.name() + "-" + n;
        ControlClient[] self = new ControlClient[1];
        self[0] = new ControlClient(socket, label, point, protocol, limits, counters, () -> {
            if (clients.remove(self[0])) {
                droppedByGone.addAndGet(self[0].dropped());
            }
        });
        clients.add(self[0]);
        LOG.debug("{}: connected from {}", label, socket.getRemoteSocketAddress());
        self[0].start();
    }

    private static void closeQuietly(Socket socket) {
        try {
            socket.close();
        } catch (IOException e) {
            // nothing left to do with it
        }
    }

    /** The engine's listener: encodes each sample once and hands it to every client's outbox. */
    private final class Fanout implements ControlPoint.Listener {

        @Override
        public void onSample(Output<?> output, Sample sample) {
            if (clients.isEmpty()) {
                return;
            }
            Frame frame;
            try {
                frame = SampleCodec.sampleFrame(output.name(), sample);
            } catch (RuntimeException e) {
                LOG.warn("control socket '{}': cannot encode a sample of {}: {}", point.name(), output, e.toString());
                return;
            }
            for (ControlClient c : clients) {
                c.offerSample(output.name(), frame);
            }
        }

        @Override
        public void onStale(boolean stale, String why) {
            Frame notice = Frame.of(JsonNodeFactory.instance.objectNode()
                    .put("type", "stale").put("stale", stale).put("why", why == null ? "" : why));
            for (ControlClient c : clients) {
                c.offerNotice(notice);
            }
        }
    }
}
