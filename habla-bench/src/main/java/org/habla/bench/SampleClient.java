package org.habla.bench;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import org.HdrHistogram.Histogram;
import org.habla.graph.EngineClock;
import org.habla.graph.RealtimeThreads;

/**
 * A control client for the benchmarks: reads sample lines from a socket, and while recording puts each
 * sample's age — now minus its source time {@code "t"} — into a histogram, counts samples and the gaps
 * in their sequence numbers.
 */
final class SampleClient implements AutoCloseable, FanOutCrowd.Figures {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final Socket socket;
    private final Thread reader;
    private final Histogram latencyMicros = new Histogram(60_000_000L, 3);
    private volatile boolean recording;
    private long samples;
    private long missing;
    private long lastSeq = -1;
    private volatile long total;

    SampleClient(int port) throws IOException {
        this(new Socket(InetAddress.getLoopbackAddress(), port), null);
    }

    /**
     * A client over {@code connected} (a plain or a TLS socket) that first sends {@code firstLine} (an auth line),
     * if not null.
     */
    SampleClient(Socket connected, String firstLine) throws IOException {
        socket = connected;
        socket.setTcpNoDelay(true);
        if (firstLine != null) {
            socket.getOutputStream().write((firstLine + "\n").getBytes(StandardCharsets.UTF_8));
            socket.getOutputStream().flush();
        }
        reader = Thread.ofPlatform().name("bench-client-" + socket.getPort()).daemon().start(this::read);
    }

    private void read() {
        RealtimeThreads.raiseCurrentIfAsked(); // as a control program run with the daemon's real-time option would
        EngineClock clock = EngineClock.system();
        try (BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                JsonNode n = JSON.readTree(line);
                if (!"sample".equals(n.path("type").asText())) {
                    continue;
                }
                long age = clock.nowMicros() - n.path("t").asLong();
                long seq = n.path("seq").asLong();
                total++;
                synchronized (this) {
                    if (recording) {
                        latencyMicros.recordValue(Math.max(0, Math.min(age, latencyMicros.getHighestTrackableValue())));
                        samples++;
                        if (lastSeq >= 0 && seq > lastSeq + 1) {
                            missing += seq - lastSeq - 1;
                        }
                    }
                    lastSeq = seq;
                }
            }
        } catch (IOException e) {
            // closed
        }
    }

    /** Samples received since connecting, recorded or not. */
    @Override
    public long total() {
        return total;
    }

    synchronized void startRecording() {
        latencyMicros.reset();
        samples = 0;
        missing = 0;
        recording = true;
    }

    synchronized void stopRecording() {
        recording = false;
    }

    @Override
    public synchronized Histogram latencyMicros() {
        return latencyMicros.copy();
    }

    @Override
    public synchronized long samples() {
        return samples;
    }

    /** Samples the sequence numbers say were never received. */
    @Override
    public synchronized long missing() {
        return missing;
    }

    @Override
    public void close() throws IOException {
        socket.close();
        try {
            reader.join(2_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
