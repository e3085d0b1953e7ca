package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;

/**
 * Waits, as an operator would with {@code habla status}, until a daemon is ready to be taught: every method
 * ready (speech has loaded its model, a worker's method is placed), every link to the robot up, and then the
 * control program connected to the sockets it uses. A teacher who starts while the robot cannot yet hear, or
 * before its control program listens, speaks to nobody, and the rewards that follow judge commands the control
 * program never heard.
 */
public final class DaemonReadiness {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final long POLL_MILLIS = 200;
    private static final int READ_TIMEOUT_MILLIS = 5_000;

    private DaemonReadiness() {
    }

    /**
     * Polls the status endpoint on loopback {@code statusPort} until nothing is missing; fails with what is still
     * missing after {@code timeoutMs}, or at once when {@code daemonAlive} says the daemon has stopped.
     */
    public static void await(int statusPort, long timeoutMs, BooleanSupplier daemonAlive)
            throws IOException, InterruptedException {
        long end = System.nanoTime() + timeoutMs * 1_000_000L;
        String missing = "no answer from the status endpoint on port " + statusPort;
        while (System.nanoTime() < end) {
            if (!daemonAlive.getAsBoolean()) {
                throw new IOException("the daemon stopped before it was ready (" + missing + ")");
            }
            try {
                List<String> notYet = missing(snapshot(statusPort));
                if (notYet.isEmpty()) {
                    return;
                }
                missing = "not ready: " + String.join(", ", notYet);
            } catch (IOException e) {
                missing = "status endpoint on port " + statusPort + ": " + e.getMessage();
            }
            Thread.sleep(POLL_MILLIS);
        }
        throw new IOException("the daemon was not ready within " + timeoutMs + " ms (" + missing + ")");
    }

    /**
     * Polls the status endpoint until each socket named in {@code sockets} has a client; fails with the sockets still
     * without one after {@code timeoutMs}, or at once when {@code clientAlive} says the client program has stopped.
     */
    public static void awaitClients(int statusPort, List<String> sockets, long timeoutMs, BooleanSupplier clientAlive)
            throws IOException, InterruptedException {
        long end = System.nanoTime() + timeoutMs * 1_000_000L;
        String missing = "no answer from the status endpoint on port " + statusPort;
        while (System.nanoTime() < end) {
            if (!clientAlive.getAsBoolean()) {
                throw new IOException("the control program stopped before it connected (" + missing + ")");
            }
            try {
                List<String> without = withoutClients(snapshot(statusPort), sockets);
                if (without.isEmpty()) {
                    return;
                }
                missing = "no client yet on " + String.join(", ", without);
            } catch (IOException e) {
                missing = "status endpoint on port " + statusPort + ": " + e.getMessage();
            }
            Thread.sleep(POLL_MILLIS);
        }
        throw new IOException("the control program did not connect within " + timeoutMs + " ms (" + missing + ")");
    }

    /** Which of {@code sockets} a status snapshot shows without a client (or not at all). */
    static List<String> withoutClients(JsonNode status, List<String> sockets) {
        List<String> out = new ArrayList<>(sockets);
        for (JsonNode s : status.path("sockets")) {
            if (s.path("clients").asInt() > 0) {
                out.remove(s.path("socket").asText());
            }
        }
        return out;
    }

    /** What a status snapshot says is not ready yet: methods by id, links as {@code link:<id>}. */
    static List<String> missing(JsonNode status) {
        List<String> out = new ArrayList<>();
        for (JsonNode m : status.path("methods")) {
            if (!m.path("ready").asBoolean()) {
                out.add(m.path("id").asText());
            }
        }
        for (JsonNode i : status.path("interfaces")) {
            if (!i.path("up").asBoolean()) {
                out.add("link:" + i.path("id").asText());
            }
        }
        if (!status.path("methods").isArray()) {
            out.add("(no methods in the status answer)");
        }
        return out;
    }

    /** One answer of the status endpoint on loopback {@code port}: every method, link and socket as the daemon sees it. */
    public static JsonNode snapshot(int port) throws IOException {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress("127.0.0.1", port), READ_TIMEOUT_MILLIS);
            s.setSoTimeout(READ_TIMEOUT_MILLIS);
            String line = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8)).readLine();
            if (line == null) {
                throw new IOException("closed without an answer");
            }
            return JSON.readTree(line);
        }
    }
}
