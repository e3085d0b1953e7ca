package org.habla.bench;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.HdrHistogram.Histogram;
import org.habla.net.Frame;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;

/**
 * A good control client for the chaos benchmarks: writes an action label with an id ten times a second and
 * times each answer, and reads the {@code distance_angle} samples. Anything but an {@code ok} to a write, a
 * write left unanswered for 5 s, or a connection that ends counts as an error (and it connects again).
 */
final class SteadyClient implements AutoCloseable {

    private static final long ANSWER_MS = 5_000;

    private final int actionPort;
    private final int readPort;
    private final Histogram answerMicros = new Histogram(60_000_000L, 3);
    private final AtomicLong samples = new AtomicLong();
    private final AtomicLong errors = new AtomicLong();
    private final AtomicLong writes = new AtomicLong();
    private volatile boolean running = true;
    private final Thread writer;
    private final Thread reader;

    SteadyClient(int actionPort, int readPort) {
        this.actionPort = actionPort;
        this.readPort = readPort;
        writer = Thread.ofPlatform().daemon().name("steady-writer").start(this::writeLoop);
        reader = Thread.ofPlatform().daemon().name("steady-reader").start(this::readLoop);
    }

    /** What happened since the last call: answers' p50/p99/max [ms], writes, errors, samples. */
    synchronized Window take() {
        Window w = new Window(answerMicros.getTotalCount() == 0 ? Double.NaN : answerMicros.getValueAtPercentile(50) / 1e3,
                answerMicros.getTotalCount() == 0 ? Double.NaN : answerMicros.getValueAtPercentile(99) / 1e3,
                answerMicros.getMaxValue() / 1e3, writes.getAndSet(0), errors.getAndSet(0), samples.getAndSet(0));
        answerMicros.reset();
        return w;
    }

    /** The good client's figures over a period. */
    record Window(double p50Ms, double p99Ms, double maxMs, long writes, long errors, long samples) {
    }

    private synchronized void record(long micros) {
        answerMicros.recordValue(Math.min(micros, answerMicros.getHighestTrackableValue()));
    }

    private void writeLoop() {
        long id = 0;
        while (running) {
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress("127.0.0.1", actionPort), (int) ANSWER_MS);
                s.setTcpNoDelay(true);
                s.setSoTimeout((int) ANSWER_MS);
                FrameReader in = new FrameReader(new BufferedInputStream(s.getInputStream()), 1 << 20, 1 << 24);
                FrameWriter out = new FrameWriter(s.getOutputStream());
                if (!"hello".equals(next(in).type())) {
                    errors.incrementAndGet();
                    continue;
                }
                long next = System.nanoTime();
                while (running) {
                    String label = (id / 100) % 2 == 0 ? "left" : "right";
                    long sent = System.nanoTime();
                    out.send(JsonNodeFactory.instance.objectNode().put("op", "write").put("value", label).put("id", ++id));
                    writes.incrementAndGet();
                    Frame f = next(in);
                    while (!f.header().path("id").isIntegralNumber() || f.header().path("id").asLong() != id) {
                        if (f.type().equals("error")) {
                            break;
                        }
                        f = next(in);
                    }
                    if (f.type().equals("ok")) {
                        record((System.nanoTime() - sent) / 1_000);
                    } else {
                        errors.incrementAndGet();
                    }
                    next += TimeUnit.MILLISECONDS.toNanos(100);
                    long wait = next - System.nanoTime();
                    if (wait > 0) {
                        TimeUnit.NANOSECONDS.sleep(wait);
                    } else {
                        next = System.nanoTime();
                    }
                }
            } catch (IOException e) {
                if (running) {
                    errors.incrementAndGet();
                }
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    private static Frame next(FrameReader in) throws IOException {
        Frame f = in.read();
        if (f == null) {
            throw new IOException("the daemon closed the connection");
        }
        return f;
    }

    private void readLoop() {
        while (running) {
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress("127.0.0.1", readPort), (int) ANSWER_MS);
                s.setSoTimeout((int) ANSWER_MS);
                FrameReader in = new FrameReader(new BufferedInputStream(s.getInputStream()), 1 << 20, 1 << 24);
                next(in);
                new FrameWriter(s.getOutputStream()).send(JsonNodeFactory.instance.objectNode().put("op", "ping"));
                while (running) {
                    Frame f = next(in);
                    if (f.type().equals("sample")) {
                        samples.incrementAndGet();
                    } else if (f.type().equals("error")) {
                        errors.incrementAndGet();
                    }
                }
            } catch (IOException e) {
                if (running) {
                    errors.incrementAndGet();
                }
            }
        }
    }

    @Override
    public void close() throws InterruptedException {
        running = false;
        writer.interrupt();
        writer.join(ANSWER_MS + 1_000);
        reader.join(ANSWER_MS + 1_000);
    }
}
