package org.habla.net;

import static java.nio.charset.StandardCharsets.UTF_8;

import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.net.SocketTimeoutException;

/** A control client for tests: a real loopback socket, the real codec, and reads that give up after 5 s. */
final class TestClient implements AutoCloseable {

    private final Socket socket;
    private final FrameReader reader;
    private final OutputStream out;

    TestClient(int port) throws IOException {
        this(port, "127.0.0.1");
    }

    /** A client whose connection comes from {@code fromAddress} (any 127.x.y.z on Linux: each a host of its own). */
    TestClient(int port, String fromAddress) throws IOException {
        socket = new Socket();
        socket.bind(new java.net.InetSocketAddress(fromAddress, 0));
        socket.connect(new java.net.InetSocketAddress("127.0.0.1", port), 5_000);
        socket.setSoTimeout(5_000);
        reader = new FrameReader(socket.getInputStream(), 1 << 20, 1 << 24);
        out = socket.getOutputStream();
    }

    /** The next frame, or null at end of stream; fails the test after 5 s of silence. */
    Frame next() throws IOException {
        try {
            return reader.read();
        } catch (SocketTimeoutException e) {
            throw new AssertionError("no frame from the server within 5 s", e);
        }
    }

    /** Skips frames (at most 10 000) until one of {@code type}. */
    Frame next(String type) throws IOException {
        for (int i = 0; i < 10_000; i++) {
            Frame f = next();
            if (f == null) {
                throw new AssertionError("the server closed before a '" + type + "' frame");
            }
            if (f.type().equals(type)) {
                return f;
            }
        }
        throw new AssertionError("no '" + type + "' frame in 10 000 frames");
    }

    void send(String line) throws IOException {
        out.write((line + "\n").getBytes(UTF_8));
        out.flush();
    }

    /** The connection itself, for tests that need to look under the codec. */
    Socket socket() {
        return socket;
    }

    void sendRaw(byte[] bytes) throws IOException {
        out.write(bytes);
        out.flush();
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
