package org.habla.bench;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.locks.LockSupport;
import org.habla.graph.EngineClock;
import org.habla.graph.RealtimeThreads;

/**
 * A robot-side interface program for the benchmarks: serves {@code habla-interface/1} on a free loopback
 * port, announces one reading channel {@code value} (a number), and once a client is connected sends a
 * reading every {@code periodNanos}, each stamped {@code "t"} with the microsecond it was written. The
 * line is built by hand so the robot itself costs next to nothing.
 */
final class BenchRobot implements AutoCloseable {

    static final String HELLO = "{\"type\":\"hello\",\"protocol\":\"habla-interface/1\",\"robot\":\"bench\","
            + "\"channels\":[{\"name\":\"value\",\"direction\":\"reading\",\"kind\":\"number\"}]}\n";
    /** The channels as the config must list them. */
    static final String CHANNELS_JSON = "[{\"name\":\"value\",\"direction\":\"reading\",\"kind\":\"number\"}]";

    /** A ring of eight range sensors (the Pioneer's front sonar, poses in the robot frame), as the sonar bench's robot
     * announces it. */
    static final String SONAR_CHANNELS_JSON = "[{\"name\":\"sonar\",\"direction\":\"reading\",\"kind\":\"vector\","
            + "\"unit\":\"m\",\"meta\":{\"maxRangeM\":5.0,\"poses\":["
            + "{\"xM\":0.069,\"yM\":0.136,\"thetaRad\":1.5708},{\"xM\":0.114,\"yM\":0.119,\"thetaRad\":0.8727},"
            + "{\"xM\":0.148,\"yM\":0.078,\"thetaRad\":0.5236},{\"xM\":0.166,\"yM\":0.027,\"thetaRad\":0.1745},"
            + "{\"xM\":0.166,\"yM\":-0.027,\"thetaRad\":-0.1745},{\"xM\":0.148,\"yM\":-0.078,\"thetaRad\":-0.5236},"
            + "{\"xM\":0.114,\"yM\":-0.119,\"thetaRad\":-0.8727},{\"xM\":0.069,\"yM\":-0.136,\"thetaRad\":-1.5708}]}}]";

    /** What a robot says first and what each reading it sends says after {@code "t":...,}. */
    record Channels(String hello, java.util.function.LongFunction<String> reading) {
        /** One number channel {@code value}, the reading's count. */
        static final Channels NUMBER = new Channels(HELLO, n -> "\"channel\":\"value\",\"value\":" + n);
        /** The sonar ring: eight ranges, one of them moving a little with every reading so the nearest changes. */
        static final Channels SONAR = new Channels("{\"type\":\"hello\",\"protocol\":\"habla-interface/1\","
                + "\"robot\":\"bench\",\"channels\":" + SONAR_CHANNELS_JSON + "}\n",
                n -> "\"channel\":\"sonar\",\"value\":[5.0,4.2,3.1," + (1.0 + (n % 100) / 100.0) + ",2.6,3.3,5.0,5.0]");
    }

    private final ServerSocket server;
    private final Channels channels;
    private final long periodNanos;
    private final Thread thread;
    private volatile long sent;
    private volatile boolean closed;

    BenchRobot(long periodNanos) throws IOException {
        this(periodNanos, Channels.NUMBER);
    }

    BenchRobot(long periodNanos, Channels channels) throws IOException {
        this.periodNanos = periodNanos;
        this.channels = channels;
        server = new ServerSocket();
        server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
        thread = Thread.ofPlatform().name("bench-robot").daemon().start(this::serve);
    }

    int port() {
        return server.getLocalPort();
    }

    /** Readings written so far. */
    long sent() {
        return sent;
    }

    private void serve() {
        RealtimeThreads.raiseCurrentIfAsked(); // as a robot's own interface server may run
        EngineClock clock = EngineClock.system();
        while (!closed) {
            try (Socket s = server.accept()) {
                s.setTcpNoDelay(true);
                OutputStream out = new BufferedOutputStream(s.getOutputStream(), 8192);
                out.write(channels.hello().getBytes(StandardCharsets.UTF_8));
                out.flush();
                long next = System.nanoTime();
                long n = 0;
                while (!closed) {
                    long wait = next - System.nanoTime();
                    if (wait > 0) {
                        LockSupport.parkNanos(wait);
                        continue;
                    }
                    n++;
                    String line = "{\"type\":\"reading\",\"t\":" + clock.nowMicros() + ","
                            + channels.reading().apply(n) + "}\n";
                    out.write(line.getBytes(StandardCharsets.UTF_8));
                    out.flush();
                    sent = n;
                    next += periodNanos;
                    if (System.nanoTime() - next > 100_000_000L) {
                        next = System.nanoTime();   // fell far behind (a pause): do not burst to catch up
                    }
                }
            } catch (IOException e) {
                // the client went away: accept the next one
            }
        }
    }

    @Override
    public void close() throws IOException {
        closed = true;
        server.close();
        try {
            thread.join(2_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
