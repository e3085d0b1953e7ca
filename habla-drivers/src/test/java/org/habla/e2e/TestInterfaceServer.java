package org.habla.e2e;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.habla.net.Frame;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;

/**
 * A robot-side interface program for end-to-end tests: serves the HABLA interface protocol on loopback,
 * announces an {@code ir} reading channel and a {@code wheels} motion command channel, streams a
 * counter on {@code ir} every 50 ms, and records every frame HABLA sends (pings aside).
 */
final class TestInterfaceServer implements AutoCloseable {

    static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    final BlockingQueue<JsonNode> received = new LinkedBlockingQueue<>();
    private final ServerSocket server;
    private final Thread acceptor;
    private volatile Socket client;
    private volatile long counter;

    TestInterfaceServer(int port) throws IOException {
        server = new ServerSocket();
        server.setReuseAddress(true);
        server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
        acceptor = Thread.ofVirtual().start(this::serve);
    }

    int port() {
        return server.getLocalPort();
    }

    static ArrayNode channels() {
        ArrayNode ch = JSON.arrayNode();
        ch.addObject().put("name", "ir").put("direction", "reading").put("kind", "vector").put("unit", "m");
        ch.addObject().put("name", "wheels").put("direction", "command").put("kind", "vector").put("unit", "m/s")
                .put("motion", true);
        return ch;
    }

    private void serve() {
        while (!server.isClosed()) {
            try (Socket s = server.accept()) {
                client = s;
                FrameWriter out = new FrameWriter(new BufferedOutputStream(s.getOutputStream()));
                ObjectNode hello = JSON.objectNode().put("type", "hello").put("protocol", "habla-interface/1")
                        .put("robot", "test-rover");
                hello.set("channels", channels());
                out.send(hello);
                Thread streamer = Thread.ofVirtual().start(() -> stream(out));
                FrameReader in = new FrameReader(new BufferedInputStream(s.getInputStream()), 65_536, 1 << 20);
                try {
                    for (Frame f = in.read(); f != null; f = in.read()) {
                        if (!"ping".equals(f.type())) {
                            received.add(f.header());
                        }
                    }
                } finally {
                    streamer.interrupt();
                }
            } catch (IOException e) {
                // the client went away or the server is closing: accept the next one
            } finally {
                client = null;
            }
        }
    }

    private void stream(FrameWriter out) {
        try {
            while (!Thread.currentThread().isInterrupted()) {
                long n = ++counter;
                ObjectNode r = JSON.objectNode().put("type", "reading").put("channel", "ir");
                r.putArray("value").add(n).add(n * 0.5);
                synchronized (out) {
                    out.send(r);
                }
                Thread.sleep(50);
            }
        } catch (IOException | InterruptedException e) {
            // connection over
        }
    }

    boolean connected() {
        return client != null;
    }

    boolean awaitClient(long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000;
        while (!connected() && System.nanoTime() < end) {
            Thread.sleep(20);
        }
        return connected();
    }

    /** The next frame of {@code type} HABLA sent, skipping others, or null after {@code millis}. */
    JsonNode next(String type, long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000;
        while (true) {
            long left = end - System.nanoTime();
            if (left <= 0) {
                return null;
            }
            JsonNode f = received.poll(left, TimeUnit.NANOSECONDS);
            if (f != null && type.equals(f.path("type").asText())) {
                return f;
            }
        }
    }

    @Override
    public void close() throws IOException {
        server.close();
        Socket c = client;
        if (c != null) {
            c.close();
        }
        try {
            acceptor.join(2_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
