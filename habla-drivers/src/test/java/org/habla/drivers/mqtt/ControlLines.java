package org.habla.drivers.mqtt;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.function.Predicate;

/** A control client for tests: a real loopback socket, JSON lines, reads that give up after 10 s. */
final class ControlLines implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final Socket socket;
    private final BufferedReader in;
    private final OutputStream out;

    ControlLines(int port) throws IOException {
        socket = new Socket("127.0.0.1", port);
        socket.setSoTimeout(30_000);
        in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
        out = socket.getOutputStream();
    }

    /** The next line that {@code wanted} accepts, skipping at most 10 000 others. */
    JsonNode next(Predicate<JsonNode> wanted, String what) throws IOException {
        for (int i = 0; i < 10_000; i++) {
            String line;
            try {
                line = in.readLine();
            } catch (SocketTimeoutException e) {
                throw new AssertionError("no " + what + " within 30 s", e);
            }
            if (line == null) {
                throw new AssertionError("the daemon closed the socket before " + what);
            }
            JsonNode n = JSON.readTree(line);
            if (wanted.test(n)) {
                return n;
            }
        }
        throw new AssertionError("no " + what + " in 10 000 lines");
    }

    JsonNode nextOfType(String type) throws IOException {
        return next(n -> n.path("type").asText().equals(type), "'" + type + "' line");
    }

    /**
     * The next line that says the socket's staleness is {@code stale}: a staleness notice, or the hello itself
     * (a link that came up before this client connected sends no notice: its hello already says fresh).
     */
    JsonNode staleness(boolean stale) throws IOException {
        return next(n -> (n.path("type").asText().equals("stale") || n.path("type").asText().equals("hello"))
                && n.path("stale").isBoolean() && n.path("stale").asBoolean() == stale, "a stale=" + stale + " line");
    }

    void send(String line) throws IOException {
        out.write((line + "\n").getBytes(StandardCharsets.UTF_8));
        out.flush();
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
