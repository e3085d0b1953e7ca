package org.habla.bench;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;

/**
 * The baseline the daemon is compared with: a plain Java TCP relay that connects to the robot, reads
 * its JSON lines, parses them, and writes a sample line for each to one client — the same socket hops
 * and the same parse/encode as the daemon, without the engine. With {@code handOffs} > 0 the value also
 * changes thread that many times over blocking queues, as it does in the daemon between the link's
 * reader, the method threads and the client's writer.
 */
final class PlainRelay implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final JsonNode END = JSON.createObjectNode();

    private final ServerSocket server;
    private final int robotPort;
    private final int handOffs;
    private final boolean virtualEnds;
    private final List<Thread> threads = new ArrayList<>();
    private volatile Socket robot;
    private volatile Socket client;

    /**
     * @param handOffs    how many times a value changes thread between reading and writing (0: never)
     * @param virtualEnds whether the socket reader and writer run on virtual threads, as in the daemon
     */
    PlainRelay(int robotPort, int handOffs, boolean virtualEnds) throws IOException {
        this.robotPort = robotPort;
        this.handOffs = handOffs;
        this.virtualEnds = virtualEnds;
        server = new ServerSocket();
        server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
        threads.add(thread(virtualEnds, "relay-reader").start(this::serve));
    }

    private static Thread.Builder thread(boolean virtual, String name) {
        return virtual ? Thread.ofVirtual().name(name) : Thread.ofPlatform().name(name).daemon();
    }

    int port() {
        return server.getLocalPort();
    }

    private void serve() {
        try {
            Socket c = server.accept();
            c.setTcpNoDelay(true);
            client = c;
            Socket r = new Socket(InetAddress.getLoopbackAddress(), robotPort);
            r.setTcpNoDelay(true);
            robot = r;
            BufferedReader in = new BufferedReader(new InputStreamReader(r.getInputStream(), StandardCharsets.UTF_8));
            BufferedWriter out = new BufferedWriter(new OutputStreamWriter(c.getOutputStream(), StandardCharsets.UTF_8));
            out.write("{\"type\":\"hello\",\"protocol\":\"plain-relay\"}\n");
            out.flush();
            in.readLine();   // the robot's hello
            BlockingQueue<JsonNode> first = new ArrayBlockingQueue<>(1024);
            BlockingQueue<JsonNode> last = first;
            for (int i = 1; i < handOffs; i++) {
                BlockingQueue<JsonNode> from = last;
                BlockingQueue<JsonNode> to = new ArrayBlockingQueue<>(1024);
                threads.add(Thread.ofPlatform().name("relay-hop-" + i).daemon().start(() -> pass(from, to)));
                last = to;
            }
            if (handOffs > 0) {
                BlockingQueue<JsonNode> tail = last;
                threads.add(thread(virtualEnds, "relay-writer").start(() -> write(tail, out)));
            }
            long seq = 0;
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                JsonNode reading = JSON.readTree(line);
                if (handOffs > 0) {
                    first.put(reading);
                } else {
                    out.write(sampleLine(reading, ++seq));
                    out.flush();
                }
            }
            first.put(END);
        } catch (IOException | InterruptedException e) {
            // closed
        }
    }

    private static void pass(BlockingQueue<JsonNode> from, BlockingQueue<JsonNode> to) {
        try {
            for (JsonNode n = from.take(); ; n = from.take()) {
                to.put(n);
                if (n == END) {
                    return;
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void write(BlockingQueue<JsonNode> from, BufferedWriter out) {
        long seq = 0;
        try {
            for (JsonNode n = from.take(); n != END; n = from.take()) {
                out.write(sampleLine(n, ++seq));
                out.flush();
            }
        } catch (InterruptedException | IOException e) {
            // closed
        }
    }

    /** The sample line a plain relay writes for {@code reading}, newline included. */
    static String sampleLine(JsonNode reading, long seq) throws IOException {
        ObjectNode s = JSON.createObjectNode().put("type", "sample").put("output", "out").put("seq", seq)
                .put("t", reading.path("t").asLong()).put("stale", false).put("kind", "number");
        s.set("value", reading.path("value"));
        return JSON.writeValueAsString(s) + "\n";
    }

    @Override
    public void close() throws IOException {
        server.close();
        for (Socket s : new Socket[] {robot, client}) {
            if (s != null) {
                s.close();
            }
        }
        for (Thread t : threads) {
            t.interrupt();
        }
    }
}
