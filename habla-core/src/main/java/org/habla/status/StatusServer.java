package org.habla.status;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Objects;
import java.util.function.Supplier;
import org.habla.config.StatusConfig;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The daemon's status endpoint: a TCP server that writes the current snapshot (rates, latencies, queue drops,
 * link states, as the engine assembles them) as one JSON line to each client that connects, then closes.
 * {@code nc 127.0.0.1 7099} is a complete client. Port 0 in the config turns it off.
 */
public final class StatusServer implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(StatusServer.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    /** A client that does not take its line within this time is dropped. */
    private static final int WRITE_TIMEOUT_MS = 2_000;

    private final StatusConfig config;
    private final Supplier<ObjectNode> snapshot;
    /** The longest {@link #close} waits for the acceptor to leave {@code accept}, which is when the port is released. */
    private static final long ACCEPTOR_STOP_MILLIS = 2_000;

    private volatile ServerSocket listener;
    private volatile Thread acceptor;
    private volatile boolean closed;

    public StatusServer(StatusConfig config, Supplier<ObjectNode> snapshot) {
        this.config = Objects.requireNonNull(config, "config");
        this.snapshot = Objects.requireNonNull(snapshot, "snapshot");
    }

    /**
     * Binds the config's port without answering anyone yet (so a daemon holds all its ports before it serves on
     * any); does nothing when the port is 0 (the endpoint is off).
     */
    public void bind() throws IOException {
        bind(config.port());
    }

    /** Binds (unless {@link #bind} did) and starts answering; does nothing when the config's port is 0. */
    public void start() throws IOException {
        if (listener == null) {
            bind(config.port());
        }
        accept();
    }

    /** Binds to an ephemeral port whatever the config says (tests, several daemons on one machine). */
    public void startOnAnyPort() throws IOException {
        bind(-1);
        accept();
    }

    private void bind(int port) throws IOException {
        if (listener != null) {
            throw new IllegalStateException("the status endpoint is already bound");
        }
        if (port == 0) {
            return;
        }
        String bind = config.bind() == null || config.bind().isBlank() ? "127.0.0.1" : config.bind();
        ServerSocket server = new ServerSocket();
        try {
            server.setReuseAddress(true);
            server.bind(new InetSocketAddress(InetAddress.getByName(bind), Math.max(port, 0)), 16);
        } catch (IOException e) {
            server.close();
            throw new IOException("status endpoint cannot listen on " + bind + ":" + port + ": " + e.getMessage(), e);
        }
        listener = server;
    }

    private void accept() {
        ServerSocket server = listener;
        if (server == null) {
            LOG.info("status endpoint is off (port 0)");
            return;
        }
        String bind = config.bind() == null || config.bind().isBlank() ? "127.0.0.1" : config.bind();
        Thread a = new Thread(this::acceptLoop, "status-accept");
        a.setDaemon(true);
        acceptor = a;
        a.start();
        LOG.info("status endpoint listening on {}:{}", bind, server.getLocalPort());
    }

    /** Whether the endpoint is listening. */
    public boolean running() {
        return listener != null && !closed;
    }

    /** The bound port. */
    public int port() {
        ServerSocket s = listener;
        if (s == null) {
            throw new IllegalStateException("the status endpoint is not listening");
        }
        return s.getLocalPort();
    }

    @Override
    public void close() {
        closed = true;
        ServerSocket s = listener;
        if (s != null) {
            try {
                s.close();
            } catch (IOException e) {
                LOG.debug("closing the status endpoint: {}", e.toString());
            }
        }
        Thread a = acceptor;
        if (a != null && a != Thread.currentThread()) {
            try {
                a.join(ACCEPTOR_STOP_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private void acceptLoop() {
        while (!closed) {
            Socket client;
            try {
                client = listener.accept();
            } catch (IOException e) {
                if (!closed) {
                    LOG.warn("status endpoint stopped accepting: {}", e.toString());
                }
                return;
            }
            Thread.ofVirtual().name("status-client").start(() -> answer(client));
        }
    }

    private void answer(Socket client) {
        try (client) {
            client.setSoTimeout(WRITE_TIMEOUT_MS);
            byte[] line;
            try {
                line = JSON.writeValueAsBytes(snapshot.get());
            } catch (RuntimeException e) {
                LOG.warn("the status snapshot failed", e);
                line = JSON.writeValueAsBytes(JSON.createObjectNode()
                        .put("type", "error").put("code", "snapshot_failed").put("message", e.toString()));
            }
            OutputStream out = client.getOutputStream();
            out.write(line);
            out.write('\n');
            out.flush();
            client.shutdownOutput();
        } catch (IOException e) {
            LOG.debug("status client {}: {}", client.getRemoteSocketAddress(), e.toString());
        }
    }
}
