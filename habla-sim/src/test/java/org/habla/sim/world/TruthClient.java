package org.habla.sim.world;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.function.Predicate;

/** A test's client of the ground-truth server: reads lines with a bounded wait and sends operations. */
public final class TruthClient implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();
    private final Socket socket;
    private final BufferedReader in;
    private final OutputStream out;

    public TruthClient(int port) throws IOException {
        socket = new Socket(InetAddress.getLoopbackAddress(), port);
        socket.setSoTimeout(5_000);
        in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
        out = socket.getOutputStream();
    }

    /** Sends one raw line. */
    public void send(String line) throws IOException {
        out.write((line + "\n").getBytes(StandardCharsets.UTF_8));
        out.flush();
    }

    /** The next line that matches, skipping others; fails after {@code maxLines} lines or a 5 s silence. */
    public JsonNode next(Predicate<JsonNode> wanted, int maxLines) throws IOException {
        for (int i = 0; i < maxLines; i++) {
            String line;
            try {
                line = in.readLine();
            } catch (SocketTimeoutException e) {
                throw new AssertionError("no line from the ground-truth server within 5 s", e);
            }
            if (line == null) {
                throw new AssertionError("the ground-truth server closed the connection");
            }
            JsonNode node = JSON.readTree(line);
            if (wanted.test(node)) {
                return node;
            }
        }
        throw new AssertionError("no matching line among " + maxLines);
    }

    /** The next ground-truth line (one with a {@code t}). */
    public JsonNode truth() throws IOException {
        return next(n -> n.has("t"), 100);
    }

    /**
     * Sends an operation and returns its reply (the next line without a {@code t}). The state lines the server
     * streamed meanwhile are skipped however many there are: a test that waited long before asking (a busy
     * machine) has many unread; the wait for the reply is bounded in time instead, {@value #REPLY_MS} ms.
     */
    public JsonNode op(String json) throws IOException {
        send(json);
        long end = System.nanoTime() + REPLY_MS * 1_000_000L;
        while (System.nanoTime() < end) {
            JsonNode n = next(x -> true, 1);
            if (!n.has("t")) {
                return n;
            }
        }
        throw new AssertionError("no reply to " + json + " within " + REPLY_MS + " ms");
    }

    /** How long {@link #op} waits for its reply. */
    static final long REPLY_MS = 30_000;

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
