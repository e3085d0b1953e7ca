package org.habla.methods.chain;

import static java.nio.charset.StandardCharsets.UTF_8;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Arrays;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A small robot behind HABLA's interface protocol on loopback, for chain tests: it announces a ring of
 * range sensors and a motion command channel, streams the ranges the test sets every 50 ms, and keeps
 * every command HABLA sends. Its threads end when it is closed.
 */
final class InterfaceRobot implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final ServerSocket server;
    private final BlockingQueue<JsonNode> received = new LinkedBlockingQueue<>();
    private final String hello;
    private volatile double[] ranges;
    private volatile boolean closed;
    private volatile Socket client;

    InterfaceRobot(String helloLine, double... initialRanges) throws IOException {
        this.hello = helloLine;
        this.ranges = initialRanges.clone();
        server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        Thread.ofVirtual().name("interface-robot").start(this::serve);
    }

    int port() {
        return server.getLocalPort();
    }

    void ranges(double... r) {
        ranges = r.clone();
    }

    /** The next line HABLA sent of {@code type}, waiting at most {@code millis}; null if none came. */
    JsonNode next(String type, long millis) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        for (long left = millis; left > 0; left = TimeUnit.NANOSECONDS.toMillis(end - System.nanoTime())) {
            JsonNode n = received.poll(left, TimeUnit.MILLISECONDS);
            if (n != null && n.path("type").asText().equals(type)) {
                return n;
            }
        }
        return null;
    }

    private void serve() {
        try (Socket s = server.accept()) {
            client = s;
            OutputStream out = s.getOutputStream();
            out.write((hello + "\n").getBytes(UTF_8));
            out.flush();
            Thread.ofVirtual().name("interface-robot-reader").start(() -> read(s));
            while (!closed) {
                String line = "{\"type\":\"reading\",\"channel\":\"sonar\",\"value\":"
                        + Arrays.toString(ranges) + "}\n";
                out.write(line.getBytes(UTF_8));
                out.flush();
                Thread.sleep(50);
            }
        } catch (IOException | InterruptedException e) {
            // closed by the test or by HABLA
        }
    }

    private void read(Socket s) {
        try {
            BufferedReader in = new BufferedReader(new InputStreamReader(s.getInputStream(), UTF_8));
            for (String line; !closed && (line = in.readLine()) != null; ) {
                received.add(JSON.readTree(line));
            }
        } catch (IOException e) {
            // closed
        }
    }

    @Override
    public void close() throws IOException {
        closed = true;
        server.close();
        Socket s = client;
        if (s != null) {
            s.close();
        }
    }
}
