package org.habla.sim.world;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.UnaryOperator;
import org.habla.net.FrameException;
import org.habla.net.LineFramer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A loopback TCP server of text lines for the simulators: it {@link #broadcast}s lines to every connected client
 * and answers each line a client sends with the line its handler returns. Each client has a bounded outbox
 * drained by its own writer, so a slow or stuck client loses lines (counted) but never holds up the sim clock
 * that broadcasts. An over-long line gets an error reply; a client that vanishes mid-line is simply forgotten.
 */
public final class LineServer implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(LineServer.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    /** The longest line a client may send. */
    public static final int MAX_LINE_BYTES = 4_096;
    /** Lines waiting for one client before new ones are dropped. */
    public static final int OUTBOX_LINES = 256;

    private final String name;
    private final UnaryOperator<String> handler;
    private final Set<Client> clients = ConcurrentHashMap.newKeySet();
    private final ServerSocket listener;
    private volatile boolean closed;
    private final LongAdder dropped = new LongAdder();

    /**
     * Binds 127.0.0.1:{@code port} (0 for any free port) and starts accepting.
     *
     * @param handler turns a client's line into the reply line, or null for no reply; null for a send-only server
     */
    public LineServer(String name, int port, UnaryOperator<String> handler) throws IOException {
        this.name = name;
        this.handler = handler;
        ServerSocket server = new ServerSocket();
        try {
            server.setReuseAddress(true);
            server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 16);
        } catch (IOException e) {
            server.close();
            throw new IOException(name + " server cannot listen on 127.0.0.1:" + port + ": " + e.getMessage(), e);
        }
        listener = server;
        Thread acceptor = new Thread(this::acceptLoop, name + "-accept");
        acceptor.setDaemon(true);
        acceptor.start();
        LOG.info("{} server listening on 127.0.0.1:{}", name, server.getLocalPort());
    }

    public int port() {
        return listener.getLocalPort();
    }

    /** How many clients are connected. */
    public int clientCount() {
        return clients.size();
    }

    /** Lines dropped because a client did not keep up. */
    public long droppedLines() {
        return dropped.sum();
    }

    /** Sends a line (without its newline) to every connected client; never blocks. */
    public void broadcast(String line) {
        byte[] bytes = (line + "\n").getBytes(StandardCharsets.UTF_8);
        for (Client c : clients) {
            c.offer(bytes);
        }
    }

    @Override
    public void close() {
        closed = true;
        try {
            listener.close();
        } catch (IOException e) {
            LOG.debug("closing the {} server: {}", name, e.toString());
        }
        for (Client c : clients) {
            c.close();
        }
    }

    private void acceptLoop() {
        while (!closed) {
            Socket socket;
            try {
                socket = listener.accept();
            } catch (IOException e) {
                if (!closed) {
                    LOG.warn("{} server stopped accepting: {}", name, e.toString());
                }
                return;
            }
            Client c = new Client(socket);
            clients.add(c);
            Thread.ofVirtual().name(name + "-write").start(c::writeLoop);
            Thread.ofVirtual().name(name + "-read").start(c::readLoop);
        }
    }

    private final class Client {
        private final Socket socket;
        private final BlockingQueue<byte[]> outbox = new ArrayBlockingQueue<>(OUTBOX_LINES);
        private volatile boolean gone;

        Client(Socket socket) {
            this.socket = socket;
        }

        void offer(byte[] line) {
            if (!gone && !outbox.offer(line)) {
                dropped.increment();
            }
        }

        void writeLoop() {
            try {
                OutputStream out = socket.getOutputStream();
                while (!gone) {
                    byte[] line = outbox.poll(200, TimeUnit.MILLISECONDS);
                    if (line == null) {
                        continue;
                    }
                    out.write(line);
                    if (outbox.isEmpty()) {
                        out.flush();
                    }
                }
            } catch (IOException e) {
                LOG.debug("{} client {} write: {}", name, socket.getRemoteSocketAddress(), e.toString());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } finally {
                close();
            }
        }

        void readLoop() {
            try {
                LineFramer framer = new LineFramer(socket.getInputStream(), MAX_LINE_BYTES);
                while (!gone) {
                    byte[] line;
                    try {
                        line = framer.readLine();
                    } catch (FrameException e) {
                        if (e.fatal()) {
                            return;
                        }
                        if (handler != null) {
                            offer(error(e.getMessage()));
                        }
                        continue;
                    }
                    if (line == null) {
                        return;
                    }
                    if (handler == null) {
                        continue;
                    }
                    String text = new String(line, StandardCharsets.UTF_8).strip();
                    if (text.isEmpty()) {
                        continue;
                    }
                    String reply;
                    try {
                        reply = handler.apply(text);
                    } catch (RuntimeException e) {
                        LOG.warn("{} server: handling a line failed", name, e);
                        reply = new String(error("internal error: " + e), StandardCharsets.UTF_8).strip();
                    }
                    if (reply != null) {
                        offer((reply + "\n").getBytes(StandardCharsets.UTF_8));
                    }
                }
            } catch (IOException e) {
                LOG.debug("{} client {} read: {}", name, socket.getRemoteSocketAddress(), e.toString());
            } finally {
                if (handler != null) {
                    close();
                }
            }
        }

        void close() {
            gone = true;
            clients.remove(this);
            try {
                socket.close();
            } catch (IOException e) {
                LOG.debug("closing a {} client: {}", name, e.toString());
            }
        }
    }

    private static byte[] error(String message) {
        return (JSON.createObjectNode().put("error", message) + "\n").getBytes(StandardCharsets.UTF_8);
    }
}
