package org.habla.drivers.tekkotsu;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.function.BooleanSupplier;

/**
 * A one-client TCP server on a loopback ephemeral port standing in for one Tekkotsu server: it
 * records every byte the client sends and runs a script that may write to the client.
 */
final class TinyServer implements AutoCloseable {

    /** What the server does once a client is connected. */
    @FunctionalInterface
    interface Script {
        void run(OutputStream toClient, TinyServer server) throws IOException, InterruptedException;
    }

    private final ServerSocket listener = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
    private final ByteArrayOutputStream received = new ByteArrayOutputStream();
    private final Thread thread;
    private volatile Socket client;
    private volatile boolean closing;

    TinyServer(Script script) throws IOException {
        thread = Thread.ofVirtual().start(() -> {
            try (Socket s = listener.accept()) {
                client = s;
                Thread recorder = Thread.ofVirtual().start(() -> record(s));
                script.run(s.getOutputStream(), this);
                recorder.join(10_000);
            } catch (IOException | InterruptedException e) {
                // closed by the test
            }
        });
    }

    private void record(Socket s) {
        try (InputStream in = s.getInputStream()) {
            byte[] b = new byte[4096];
            int n;
            while ((n = in.read(b)) > 0) {
                synchronized (received) {
                    received.write(b, 0, n);
                }
            }
        } catch (IOException e) {
            // the client went away
        }
    }

    /** Keeps the connection open, saying nothing, until the test ends (at most 60 s). */
    void holdOpen() throws InterruptedException {
        await(Duration.ofSeconds(60), () -> closing);
    }

    /** Drops the client, as a robot that crashes does. */
    void hangUp() throws IOException {
        client.close();
    }

    int port() {
        return listener.getLocalPort();
    }

    byte[] received() {
        synchronized (received) {
            return received.toByteArray();
        }
    }

    String receivedText() {
        return new String(received(), StandardCharsets.ISO_8859_1);
    }

    /** Waits up to {@code limit} for {@code condition}; true if it came. */
    static boolean await(Duration limit, BooleanSupplier condition) throws InterruptedException {
        long end = System.nanoTime() + limit.toNanos();
        while (System.nanoTime() < end) {
            if (condition.getAsBoolean()) {
                return true;
            }
            Thread.sleep(10);
        }
        return condition.getAsBoolean();
    }

    @Override
    public void close() throws IOException {
        closing = true;
        Socket c = client;
        if (c != null) {
            c.close();
        }
        listener.close();
        try {
            thread.join(2_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
