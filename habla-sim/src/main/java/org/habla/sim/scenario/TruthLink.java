package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * The scenario's line to the simulator's ground truth: it reads the world's state lines (the robot's
 * pose, the object, the teacher) and sends the operations that run an episode (reset, teacher on or
 * off). Replies and state lines arrive on the same stream; replies are told apart by their {@code ok}
 * or {@code error} key.
 */
public final class TruthLink implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final Socket socket;
    private final BufferedReader in;
    private final OutputStream out;
    private final BlockingQueue<JsonNode> replies = new LinkedBlockingQueue<>();
    private volatile JsonNode latest;
    private final Thread reader;

    private TruthLink(Socket socket) throws IOException {
        this.socket = socket;
        this.in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
        this.out = socket.getOutputStream();
        this.reader = Thread.ofPlatform().daemon().name("habla-scenario-truth").start(this::readLoop);
    }

    /** Connects, retrying until {@code timeoutMs} has passed (the simulator may still be starting). */
    public static TruthLink connect(int port, long timeoutMs) throws IOException, InterruptedException {
        return connect(port, timeoutMs, () -> true);
    }

    /** Connects, retrying while {@code serverAlive} says the simulator still runs. */
    public static TruthLink connect(int port, long timeoutMs, java.util.function.BooleanSupplier serverAlive)
            throws IOException, InterruptedException {
        long end = System.nanoTime() + timeoutMs * 1_000_000L;
        IOException last = null;
        while (System.nanoTime() < end) {
            if (!serverAlive.getAsBoolean()) {
                throw new IOException("the simulator stopped before its ground truth on port " + port + " opened");
            }
            Socket s = new Socket();
            try {
                s.connect(new InetSocketAddress("127.0.0.1", port), 1_000);
                return new TruthLink(s);
            } catch (IOException e) {
                s.close();
                last = e;
                Thread.sleep(100);
            }
        }
        throw new IOException("the simulator's ground truth on port " + port + " did not answer within "
                + timeoutMs + " ms" + (last == null ? "" : ": " + last.getMessage()));
    }

    private void readLoop() {
        try {
            String line;
            while ((line = in.readLine()) != null) {
                JsonNode n;
                try {
                    n = JSON.readTree(line);
                } catch (IOException e) {
                    continue;
                }
                if (n.has("ok") || n.has("error")) {
                    replies.add(n);
                } else if (n.isObject()) {
                    latest = n;
                }
            }
        } catch (IOException e) {
            // closed
        }
    }

    /** The newest state line, or null before the first. */
    public JsonNode latest() {
        return latest;
    }

    /** Sends an operation and waits for its reply; an {@code error} reply becomes an exception. */
    public synchronized JsonNode send(ObjectNode op) throws IOException, InterruptedException {
        replies.clear();
        out.write((JSON.writeValueAsString(op) + "\n").getBytes(StandardCharsets.UTF_8));
        out.flush();
        JsonNode r = replies.poll(5, TimeUnit.SECONDS);
        if (r == null) {
            throw new IOException("the simulator did not answer " + op);
        }
        if (r.has("error")) {
            throw new IOException("the simulator refused " + op + ": " + r.path("error").asText());
        }
        return r;
    }

    public static ObjectNode op(String name) {
        return JSON.createObjectNode().put("op", name);
    }

    /** Waits for a state line whose simulated time is at least {@code t}; null if none within {@code timeoutMs}. */
    public JsonNode awaitTime(double t, long timeoutMs) throws InterruptedException {
        long end = System.nanoTime() + timeoutMs * 1_000_000L;
        while (System.nanoTime() < end) {
            JsonNode n = latest;
            if (n != null && n.path("t").asDouble() >= t) {
                return n;
            }
            Thread.sleep(5);
        }
        return null;
    }

    boolean alive() {
        return reader.isAlive();
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
