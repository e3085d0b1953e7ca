package org.habla.drivers.tekkotsu;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.concurrent.atomic.AtomicReference;
import org.habla.driver.Connection;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.sample.Payload;

/**
 * Runs one driver connection over a real loopback socket the way the engine does — handshake,
 * a reader thread calling {@code readNext} with the connection's silence limit, keep-alives on their own
 * thread, writes under a lock —
 * for tests that have no engine.
 */
final class LoopbackLink implements AutoCloseable {

    private final Socket socket = new Socket();
    private final LinkSession session;
    private final OutputStream out;
    private final Thread reader;
    private final Thread keepAlive;
    final AtomicReference<Throwable> ended = new AtomicReference<>();

    LoopbackLink(int port, Connection connection, ReadingSink sink) throws IOException {
        socket.connect(new InetSocketAddress("127.0.0.1", port), 2_000);
        socket.setSoTimeout(15_000);
        InputStream in = new BufferedInputStream(socket.getInputStream());
        out = new BufferedOutputStream(socket.getOutputStream());
        session = connection.sessions().get();
        session.handshake(in, out, sink);
        out.flush();
        // as the engine does: a periodic stream times out after its silence limit, a quiet one never
        socket.setSoTimeout((int) connection.liveness().silenceLimit().toMillis());
        reader = Thread.ofVirtual().start(() -> {
            try {
                while (!socket.isClosed()) {
                    session.readNext(in, sink);
                }
            } catch (IOException | RuntimeException e) {
                ended.set(e);
            }
        });
        keepAlive = Thread.ofVirtual().start(() -> session.keepAlivePeriod().ifPresent(period -> {
            try {
                while (!socket.isClosed()) {
                    Thread.sleep(period);
                    synchronized (this) {
                        session.keepAlive(out);
                        out.flush();
                    }
                }
            } catch (InterruptedException | IOException e) {
                // the link is closing
            }
        }));
    }

    synchronized void write(String channel, Payload value) throws IOException {
        session.write(channel, value, out);
        out.flush();
    }

    synchronized void stopMotion() throws IOException {
        session.stopMotion(out);
        out.flush();
    }

    @Override
    public void close() throws IOException {
        synchronized (this) {
            try {
                session.goodbye(out);
                out.flush();
            } catch (IOException e) {
                // the peer may be gone already
            }
        }
        socket.close();
        keepAlive.interrupt();
        try {
            reader.join(2_000);
            keepAlive.join(2_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
