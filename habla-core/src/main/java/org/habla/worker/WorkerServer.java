package org.habla.worker;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import org.habla.config.Limits;
import org.habla.graph.EngineClock;
import org.habla.net.FrameWriter;
import org.habla.net.WorkerProtocol;
import org.habla.plugin.PluginRegistry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The listening side of {@code habla worker}: accepts daemon connections, each running one placed method
 * in a {@link WorkerSession} of its own. At most {@link #MAX_SESSIONS} at once; the next connection gets a
 * {@code too_many_methods} error line and is closed.
 */
public final class WorkerServer implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(WorkerServer.class);
    /** Methods one worker runs at once. */
    public static final int MAX_SESSIONS = 64;

    private final PluginRegistry registry;
    private final String bind;
    private final int requestedPort;
    private final EngineClock clock;
    private final Limits limits;
    private final Set<Socket> sessions = ConcurrentHashMap.newKeySet();
    private final ExecutorService backgroundPool;
    private volatile boolean running;
    private ServerSocket server;
    private Thread acceptor;

    public WorkerServer(PluginRegistry registry, String bind, int port, EngineClock clock, Limits limits) {
        this.registry = registry;
        this.bind = bind;
        this.requestedPort = port;
        this.clock = clock;
        this.limits = limits;
        AtomicInteger n = new AtomicInteger();
        this.backgroundPool = Executors.newFixedThreadPool(Math.max(2, Runtime.getRuntime().availableProcessors()),
                r -> {
                    Thread t = new Thread(r, "habla-worker-background-" + n.incrementAndGet());
                    t.setDaemon(true);
                    return t;
                });
    }

    /** Binds the port and starts accepting. */
    public synchronized void start() throws IOException {
        ServerSocket s = new ServerSocket();
        s.setReuseAddress(true);
        try {
            s.bind(new InetSocketAddress(InetAddress.getByName(bind), requestedPort), 50);
        } catch (IOException e) {
            s.close();
            throw new IOException("cannot listen on " + bind + ":" + requestedPort + ": " + e.getMessage(), e);
        }
        server = s;
        running = true;
        acceptor = Thread.ofPlatform().daemon().name("habla-worker-accept").start(this::acceptLoop);
        LOG.info("HABLA worker listening on {}:{}; method types: {}", bind, port(),
                String.join(", ", registry.methods().keySet()));
    }

    /** The bound port (useful when 0 was asked for). */
    public int port() {
        return server.getLocalPort();
    }

    /** Connections running a method now. */
    public int sessions() {
        return sessions.size();
    }

    private void acceptLoop() {
        while (running) {
            Socket s;
            try {
                s = server.accept();
            } catch (IOException e) {
                if (running) {
                    LOG.warn("accept failed: {}", e.toString());
                }
                continue;
            }
            if (sessions.size() >= MAX_SESSIONS) {
                refuse(s);
                continue;
            }
            sessions.add(s);
            WorkerSession session = new WorkerSession(s, registry, clock, backgroundPool, limits);
            Thread.ofVirtual().name("habla-worker-session").start(() -> {
                try {
                    session.run();
                } finally {
                    sessions.remove(s);
                }
            });
        }
    }

    private static void refuse(Socket s) {
        try (s) {
            FrameWriter w = new FrameWriter(s.getOutputStream());
            w.send(WorkerProtocol.error("too_many_methods", "this worker runs " + MAX_SESSIONS + " methods already"));
        } catch (IOException e) {
            LOG.debug("refusing a connection: {}", e.toString());
        }
    }

    /** Stops accepting, closes every connection (their methods stop) and the background pool. */
    @Override
    public synchronized void close() {
        running = false;
        try {
            if (server != null) {
                server.close();
            }
        } catch (IOException e) {
            LOG.debug("close: {}", e.toString());
        }
        for (Socket s : sessions) {
            try {
                s.close();
            } catch (IOException e) {
                LOG.debug("close: {}", e.toString());
            }
        }
        if (acceptor != null) {
            try {
                acceptor.join(2_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        backgroundPool.shutdownNow();
    }
}
