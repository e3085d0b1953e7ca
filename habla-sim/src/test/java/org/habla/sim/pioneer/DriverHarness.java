package org.habla.sim.pioneer;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Predicate;
import org.habla.driver.Connection;
import org.habla.driver.InterfaceAddress;
import org.habla.driver.LinkSession;
import org.habla.driver.ReadingSink;
import org.habla.drivers.pioneer.PioneerDriver;
import org.habla.drivers.pioneer.PioneerParams;
import org.habla.sample.Payload;

/**
 * HABLA's real Pioneer driver session on a real socket to the simulator, run the way the engine runs it: the
 * handshake, a reader thread decoding SIPs into readings, keep-alives at the given period, commands written on
 * demand. Tests wait on readings with bounded waits.
 */
final class DriverHarness implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final Socket socket;
    private final InputStream in;
    private final OutputStream out;
    private final LinkSession session;
    private final Map<String, Payload> latest = new ConcurrentHashMap<>();
    private final List<ObjectNode> robotInfo = new CopyOnWriteArrayList<>();
    private final List<String> malformed = new CopyOnWriteArrayList<>();
    private final Object arrivals = new Object();
    private volatile boolean keepAlive = true;
    private volatile boolean closed;

    /**
     * Connects, runs the driver's handshake and starts reading.
     *
     * @param keepAliveMs real milliseconds between PULSEs (the driver's keepAlivePeriodMs)
     */
    DriverHarness(int port, int keepAliveMs) throws IOException {
        ObjectNode params = JSON.createObjectNode().put("keepAlivePeriodMs", keepAliveMs);
        PioneerParams p = JSON.treeToValue(params, PioneerParams.class);
        Connection c = new PioneerDriver(new InterfaceAddress("127.0.0.1", OptionalInt.of(port)), p).connections().get(0);
        session = c.sessions().get();
        socket = new Socket(InetAddress.getLoopbackAddress(), port);
        socket.setSoTimeout(5_000);
        in = new BufferedInputStream(socket.getInputStream());
        out = new BufferedOutputStream(socket.getOutputStream());
        session.handshake(in, out, sink());
        out.flush();
        Thread reader = new Thread(this::readLoop, "harness-read");
        reader.setDaemon(true);
        reader.start();
        Thread pulser = new Thread(() -> pulseLoop(keepAliveMs), "harness-pulse");
        pulser.setDaemon(true);
        pulser.start();
    }

    /** Stops (or restarts) the keep-alives, as a client that falls silent. */
    void keepAlive(boolean on) {
        keepAlive = on;
    }

    synchronized void command(String channel, Payload value) throws IOException {
        session.write(channel, value, out);
        out.flush();
    }

    synchronized void pulse() throws IOException {
        session.keepAlive(out);
        out.flush();
    }

    List<ObjectNode> robotInfo() {
        return robotInfo;
    }

    List<String> malformed() {
        return malformed;
    }

    /** Waits (at most {@code timeoutMs} real ms) for a reading on {@code channel} that satisfies {@code test}. */
    @SuppressWarnings("unchecked")
    <T extends Payload> T await(String channel, Class<T> type, Predicate<T> test, long timeoutMs)
            throws InterruptedException {
        long deadline = System.currentTimeMillis() + timeoutMs;
        synchronized (arrivals) {
            while (true) {
                Payload p = latest.get(channel);
                if (type.isInstance(p) && test.test((T) p)) {
                    return (T) p;
                }
                long left = deadline - System.currentTimeMillis();
                if (left <= 0) {
                    throw new AssertionError("no matching '" + channel + "' reading within " + timeoutMs
                            + " ms; last: " + p);
                }
                arrivals.wait(left);
            }
        }
    }

    /** Leaves abruptly, without CLOSE, as a client that crashes. */
    void vanish() throws IOException {
        closed = true;
        socket.close();
    }

    /** Says goodbye (CLOSE) and leaves. */
    @Override
    public void close() throws IOException {
        if (!closed) {
            synchronized (this) {
                session.goodbye(out);
                out.flush();
            }
        }
        vanish();
    }

    private void readLoop() {
        ReadingSink sink = sink();
        try {
            while (!closed) {
                session.readNext(in, sink);
            }
        } catch (IOException e) {
            // the test closed the socket, or the simulator left: the test's waits tell
        }
    }

    private void pulseLoop(int periodMs) {
        while (!closed) {
            try {
                Thread.sleep(periodMs);
                if (keepAlive && !closed) {
                    pulse();
                }
            } catch (InterruptedException | IOException e) {
                return;
            }
        }
    }

    private ReadingSink sink() {
        return new ReadingSink() {
            @Override
            public Channel channel(String name) {
                return Channel.of(value -> reading(name, value), (value, micros) -> reading(name, value, micros));
            }

            @Override
            public void reading(String channel, Payload value) {
                latest.put(channel, value);
                synchronized (arrivals) {
                    arrivals.notifyAll();
                }
            }

            @Override
            public void reading(String channel, Payload value, long sourceMicros) {
                reading(channel, value);
            }

            @Override
            public void malformed(String what) {
                malformed.add(what);
            }

            @Override
            public void robotInfo(ObjectNode info) {
                robotInfo.add(info);
            }
        };
    }
}
