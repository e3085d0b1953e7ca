package org.habla.bench;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.HdrHistogram.Histogram;

/**
 * Many control clients read by one thread: each is a socket of its own, and one selector thread takes whatever
 * lines have arrived on any of them, stamps each sample's age (now minus its source time {@code "t"}) and checks
 * its sequence number. On a two-core machine, 200 reading threads would spend more time being scheduled than
 * the daemon spends writing to them; a crowd of separate machines has no such cost, and one selector comes
 * closer to it. The two fields are found by scanning the line, not by parsing it whole, for the same reason.
 */
final class CrowdReader implements AutoCloseable {

    private static final byte[] T = "\"t\":".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
    private static final byte[] SEQ = "\"seq\":".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
    private static final byte[] SAMPLE = "\"type\":\"sample\"".getBytes(java.nio.charset.StandardCharsets.US_ASCII);

    /** One client's socket, its partial line and its figures. */
    static final class Client implements FanOutCrowd.Figures {
        private final SocketChannel channel;
        private final byte[] line = new byte[65_536];
        private int length;
        private final Histogram latencyMicros = new Histogram(60_000_000L, 3);
        private long samples;
        private long missing;
        private long lastSeq = -1;
        private volatile long total;

        private Client(SocketChannel channel) {
            this.channel = channel;
        }

        @Override
        public long total() {
            return total;
        }

        @Override
        public synchronized Histogram latencyMicros() {
            return latencyMicros.copy();
        }

        @Override
        public synchronized long samples() {
            return samples;
        }

        @Override
        public synchronized long missing() {
            return missing;
        }
    }

    private final Selector selector;
    private final List<Client> clients = new ArrayList<>();
    private final Thread thread;
    private volatile boolean recording;
    private volatile boolean closed;

    /** Connects {@code count} clients to {@code port}, one after another, and starts reading them. */
    CrowdReader(int port, int count) throws IOException {
        selector = Selector.open();
        for (int i = 0; i < count; i++) {
            SocketChannel ch = SocketChannel.open(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
            ch.socket().setTcpNoDelay(true);
            ch.configureBlocking(false);
            Client c = new Client(ch);
            ch.register(selector, SelectionKey.OP_READ, c);
            clients.add(c);
        }
        thread = Thread.ofPlatform().name("bench-crowd-reader").daemon().start(this::loop);
    }

    /** The clients in the order they connected. */
    List<Client> clients() {
        return clients;
    }

    void startRecording() {
        for (Client c : clients) {
            synchronized (c) {
                c.latencyMicros.reset();
                c.samples = 0;
                c.missing = 0;
            }
        }
        recording = true;
    }

    void stopRecording() {
        recording = false;
    }

    private void loop() {
        ByteBuffer buffer = ByteBuffer.allocateDirect(1 << 16);
        byte[] bytes = new byte[1 << 16];
        try {
            while (!closed) {
                selector.select();
                for (SelectionKey key : selector.selectedKeys()) {
                    Client c = (Client) key.attachment();
                    buffer.clear();
                    int n = c.channel.read(buffer);
                    if (n < 0) {
                        key.cancel();
                        continue;
                    }
                    long now = nowMicros();
                    buffer.flip();
                    buffer.get(bytes, 0, n);
                    take(c, bytes, n, now);
                }
                selector.selectedKeys().clear();
            }
        } catch (IOException | java.nio.channels.ClosedSelectorException e) {
            // closed
        }
    }

    private void take(Client c, byte[] bytes, int n, long now) {
        for (int i = 0; i < n; i++) {
            if (bytes[i] != '\n') {
                if (c.length < c.line.length) {
                    c.line[c.length++] = bytes[i];
                }
                continue;
            }
            if (indexOf(c.line, c.length, SAMPLE) >= 0) {
                sample(c, number(c.line, c.length, T), number(c.line, c.length, SEQ), now);
            }
            c.length = 0;
        }
    }

    private void sample(Client c, long t, long seq, long now) {
        c.total++;
        synchronized (c) {
            if (recording) {
                long age = now - t;
                c.latencyMicros.recordValue(Math.max(0, Math.min(age, c.latencyMicros.getHighestTrackableValue())));
                c.samples++;
                if (c.lastSeq >= 0 && seq > c.lastSeq + 1) {
                    c.missing += seq - c.lastSeq - 1;
                }
            }
            c.lastSeq = seq;
        }
    }

    /** The whole number after {@code key} in the line, or -1. */
    private static long number(byte[] line, int length, byte[] key) {
        int at = indexOf(line, length, key);
        if (at < 0) {
            return -1;
        }
        long v = 0;
        for (int i = at + key.length; i < length && line[i] >= '0' && line[i] <= '9'; i++) {
            v = v * 10 + (line[i] - '0');
        }
        return v;
    }

    private static int indexOf(byte[] line, int length, byte[] key) {
        outer:
        for (int i = 0; i + key.length <= length; i++) {
            for (int j = 0; j < key.length; j++) {
                if (line[i + j] != key[j]) {
                    continue outer;
                }
            }
            return i;
        }
        return -1;
    }

    private static long nowMicros() {
        Instant now = Instant.now();
        return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000;
    }

    @Override
    public void close() throws IOException {
        closed = true;
        selector.close();
        for (Client c : clients) {
            c.channel.close();
        }
        try {
            thread.join(2_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
