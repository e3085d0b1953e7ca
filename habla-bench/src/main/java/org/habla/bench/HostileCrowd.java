package org.habla.bench;

import static java.nio.charset.StandardCharsets.UTF_8;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicIntegerArray;

/**
 * Hostile and careless connections for the chaos benchmarks, of every kind issue 9 names, spread over a list
 * of ports: each connects (all at once, the parallel connects), does its harm, then reads until the daemon
 * answers it with an error line or closes it. Counts the outcomes by kind.
 */
final class HostileCrowd implements AutoCloseable {

    /** What a hostile connection does. */
    enum Kind {
        /** connects, sends nothing, reads */
        IDLE,
        /** sends a line one byte a second */
        SLOWLORIS,
        /** connects and neither reads nor sends (until the benchmark looks) */
        HOLD_UNREAD,
        /** declares an 8 MiB block, sends 4 KiB of it, then nothing */
        HUGE_BYTES,
        /** sends 64 KiB of random bytes, then nothing */
        GARBAGE
    }

    /** How a connection ended: told why, then closed; closed; still open when the crowd was closed. */
    enum Outcome { ANSWERED, CLOSED, OPEN }

    private final ExecutorService threads = Executors.newVirtualThreadPerTaskExecutor();
    private final ConcurrentLinkedQueue<Socket> sockets = new ConcurrentLinkedQueue<>();
    private final AtomicIntegerArray outcomes = new AtomicIntegerArray(Kind.values().length * Outcome.values().length);
    private volatile boolean closing;
    private volatile boolean reading;

    /** Starts {@code count} connections, the kinds in turn, the ports in turn. */
    void launch(int count, List<Integer> ports, long seed) {
        for (int i = 0; i < count; i++) {
            Kind kind = Kind.values()[i % Kind.values().length];
            int port = ports.get(i / Kind.values().length % ports.size());
            long s = seed + i;
            threads.submit(() -> {
                Outcome o = attack(port, kind, s);
                outcomes.incrementAndGet(kind.ordinal() * Outcome.values().length + o.ordinal());
            });
        }
    }

    /** Lets the connections that hold without reading look at what the daemon did to them. */
    void startReading() {
        reading = true;
    }

    /** Connections that have ended, and how, by kind. */
    Map<Kind, Map<Outcome, Integer>> outcomes() {
        Map<Kind, Map<Outcome, Integer>> m = new EnumMap<>(Kind.class);
        for (Kind k : Kind.values()) {
            Map<Outcome, Integer> byOutcome = new EnumMap<>(Outcome.class);
            for (Outcome o : Outcome.values()) {
                byOutcome.put(o, outcomes.get(k.ordinal() * Outcome.values().length + o.ordinal()));
            }
            m.put(k, byOutcome);
        }
        return m;
    }

    /** Connections that have ended, all kinds. */
    int ended() {
        int n = 0;
        for (int i = 0; i < outcomes.length(); i++) {
            n += outcomes.get(i);
        }
        return n;
    }

    private Outcome attack(int port, Kind kind, long seed) {
        try (Socket s = new Socket()) {
            sockets.add(s);
            s.connect(new InetSocketAddress("127.0.0.1", port), 30_000);
            OutputStream out = s.getOutputStream();
            switch (kind) {
                case IDLE, HOLD_UNREAD -> { }
                case SLOWLORIS -> {
                    byte[] line = "{\"op\":\"ping\",\"pad\":\"zzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzz\"}"
                            .getBytes(UTF_8);
                    for (byte b : line) {
                        out.write(b);
                        out.flush();
                        Outcome o = readFor(s, 1_000); // one byte a second
                        if (o != Outcome.OPEN) {
                            return o;
                        }
                    }
                }
                case HUGE_BYTES -> {
                    out.write("{\"op\":\"write\",\"kind\":\"audio\",\"rateHz\":16000,\"channels\":1,\"bits\":16,\"bytes\":8388608}\n"
                            .getBytes(UTF_8));
                    out.write(new byte[4_096]);
                    out.flush();
                }
                case GARBAGE -> {
                    byte[] noise = new byte[65_536];
                    new Random(seed).nextBytes(noise);
                    out.write(noise);
                    out.flush();
                }
            }
            if (kind == Kind.HOLD_UNREAD) {
                while (!closing && !reading) {
                    Thread.sleep(100); // holds the connection, reads nothing, until told to look
                }
            }
            return readFor(s, Long.MAX_VALUE);
        } catch (IOException e) {
            return closing ? Outcome.OPEN : Outcome.CLOSED; // refused, reset, broken pipe: the daemon closed it
        } catch (InterruptedException e) {
            return Outcome.OPEN;
        }
    }

    /** Reads until the daemon closes or {@code millis} pass (or the crowd is closed): the outcome so far. */
    private Outcome readFor(Socket s, long millis) throws IOException {
        s.setSoTimeout((int) Math.min(millis, 1_000));
        InputStream in = s.getInputStream();
        byte[] buf = new byte[4_096];
        boolean answered = false;
        long until = millis == Long.MAX_VALUE ? Long.MAX_VALUE : System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        while (!closing && System.nanoTime() - until < 0) {
            int n;
            try {
                n = in.read(buf);
            } catch (SocketTimeoutException e) {
                continue;
            } catch (IOException e) {
                return closing ? Outcome.OPEN : answered ? Outcome.ANSWERED : Outcome.CLOSED;
            }
            if (n < 0) {
                return answered ? Outcome.ANSWERED : Outcome.CLOSED;
            }
            answered |= new String(buf, 0, n, UTF_8).contains("\"type\":\"error\"");
        }
        return Outcome.OPEN;
    }

    /** Ends what is still open (counted as OPEN) and waits for every connection's thread. */
    @Override
    public void close() throws InterruptedException {
        closing = true;
        for (Socket s : sockets) {
            try {
                s.close();
            } catch (IOException e) {
                // closing anyway
            }
        }
        threads.shutdownNow();
        threads.awaitTermination(30, TimeUnit.SECONDS);
    }
}
