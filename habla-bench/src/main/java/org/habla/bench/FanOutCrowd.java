package org.habla.bench;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.HdrHistogram.Histogram;
import org.habla.daemon.Daemon;

/**
 * Benchmark (c)'s crowd round: many reading clients on one exposed socket at a slow robot rate, plus one
 * client that connects and never reads. Prints each client's p50 and p99 by its place in the connection
 * order, so a delivery that writes to clients one after another shows as a slope: the first twenty, the
 * middle twenty and the last twenty, the worst client, and how many microseconds a client's p50 grows per
 * client connected before it. The readers are one selector thread ({@link CrowdReader}), or with
 * {@code threadPerClient} one {@link SampleClient} thread each.
 */
final class FanOutCrowd {

    private static final int GROUP = 20;

    /** What one reading client counted while recording. */
    interface Figures {
        /** Samples received since connecting, recorded or not. */
        long total();

        Histogram latencyMicros();

        long samples();

        /** Samples the sequence numbers say were never received. */
        long missing();
    }

    private final int clients;
    private final int rateHz;
    private final int warmupS;
    private final int seconds;
    private final boolean threadPerClient;

    FanOutCrowd(int clients, int rateHz, int warmupS, int seconds, boolean threadPerClient) {
        this.clients = clients;
        this.rateHz = rateHz;
        this.warmupS = warmupS;
        this.seconds = seconds;
        this.threadPerClient = threadPerClient;
    }

    void run() throws Exception {
        System.out.printf("%n(c) fan-out crowd: %d reading clients (%s) + 1 that never reads, robot at %d Hz, %d s "
                + "warm-up, %d s measured%n", clients, threadPerClient ? "a thread each" : "one selector thread",
                rateHz, warmupS, seconds);
        try (BenchRobot robot = new BenchRobot(1_000_000_000L / rateHz)) {
            Daemon daemon = BenchDaemon.start(robot.port());
            try {
                System.out.println("the daemon: channel -> pass-through x2, the exposed socket");
                long droppedBefore = FanOutBench.dropped(daemon);
                measure(daemon.port("value"), () -> FanOutBench.dropped(daemon) - droppedBefore);
            } finally {
                daemon.close();
            }
        }
        for (PlainFanout.Writers writers : PlainFanout.Writers.values()) {
            try (BenchRobot robot = new BenchRobot(1_000_000_000L / rateHz);
                    PlainFanout plain = new PlainFanout(robot.port(), writers)) {
                System.out.printf("%n%s%n", writers.title);
                measure(plain.port(), plain::start, () -> 0L);
            }
        }
    }

    private void measure(int port, java.util.function.LongSupplier dropped) throws Exception {
        measure(port, () -> { }, dropped);
    }

    /** Connects the readers and the silent client to {@code port}, runs {@code begin}, warms up, measures, prints. */
    private void measure(int port, Runnable begin, java.util.function.LongSupplier dropped) throws Exception {
        List<SampleClient> threads = new ArrayList<>();
        CrowdReader crowd = null;
        Socket silent = new Socket();
        try {
            List<Figures> readers = new ArrayList<>();
            if (threadPerClient) {
                for (int i = 0; i < clients; i++) {
                    threads.add(new SampleClient(port));
                }
                readers.addAll(threads);
            } else {
                crowd = new CrowdReader(port, clients);
                readers.addAll(crowd.clients());
            }
            silent.setReceiveBufferSize(4096);
            silent.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
            begin.run();
            for (Figures c : readers) {
                LatencyBench.await(() -> c.total() > 0, 20_000, "no sample reached a fan-out client");
            }
            Thread.sleep(warmupS * 1000L);
            long droppedBefore = dropped.getAsLong();
            threads.forEach(SampleClient::startRecording);
            if (crowd != null) {
                crowd.startRecording();
            }
            Thread.sleep(seconds * 1000L);
            threads.forEach(SampleClient::stopRecording);
            if (crowd != null) {
                crowd.stopRecording();
            }
            print(readers, dropped.getAsLong() - droppedBefore);
        } finally {
            for (SampleClient c : threads) {
                c.close();
            }
            if (crowd != null) {
                crowd.close();
            }
            silent.close();
        }
    }

    private void print(List<Figures> readers, long dropped) {
        int n = readers.size();
        long[] p50 = new long[n];
        long[] p99 = new long[n];
        long lost = 0;
        long received = 0;
        Histogram all = new Histogram(60_000_000L, 3);
        for (int i = 0; i < n; i++) {
            Histogram h = readers.get(i).latencyMicros();
            p50[i] = h.getValueAtPercentile(50);
            p99[i] = h.getValueAtPercentile(99);
            lost += readers.get(i).missing();
            received += readers.get(i).samples();
            all.add(h);
        }
        System.out.printf("%-22s %14s %14s %14s%n", "by connection order", "median p50 µs", "max p50 µs", "max p99 µs");
        group("first " + Math.min(GROUP, n), p50, p99, 0, Math.min(GROUP, n));
        int mid = Math.max(0, n / 2 - GROUP / 2);
        group("middle " + Math.min(GROUP, n), p50, p99, mid, Math.min(n, mid + GROUP));
        group("last " + Math.min(GROUP, n), p50, p99, Math.max(0, n - GROUP), n);
        group("all " + n, p50, p99, 0, n);
        int worst50 = argMax(p50);
        int worst99 = argMax(p99);
        System.out.printf("worst client: p50 %d µs (position %d), p99 %d µs (position %d); all samples together: "
                + "p50 %d, p99 %d µs%n", p50[worst50], worst50 + 1, p99[worst99], worst99 + 1,
                all.getValueAtPercentile(50), all.getValueAtPercentile(99));
        System.out.printf("p50 grows by %.1f µs per client connected before (least squares over positions)%n",
                slope(p50));
        System.out.printf("received %d samples, lost %d (sequence gaps at the readers); the daemon dropped %d from "
                + "client queues while measuring (the silent client's, if the readers lost none)%n",
                received, lost, dropped);
    }

    private static void group(String name, long[] p50, long[] p99, int from, int to) {
        long[] a = Arrays.copyOfRange(p50, from, to);
        long[] b = Arrays.copyOfRange(p99, from, to);
        Arrays.sort(a);
        Arrays.sort(b);
        System.out.printf("%-22s %14d %14d %14d%n", name, a[a.length / 2], a[a.length - 1], b[b.length - 1]);
    }

    private static int argMax(long[] v) {
        int at = 0;
        for (int i = 1; i < v.length; i++) {
            if (v[i] > v[at]) {
                at = i;
            }
        }
        return at;
    }

    private static double slope(long[] y) {
        int n = y.length;
        if (n < 2) {
            return 0;
        }
        double mx = (n - 1) / 2.0;
        double my = Arrays.stream(y).average().orElse(0);
        double num = 0;
        double den = 0;
        for (int i = 0; i < n; i++) {
            num += (i - mx) * (y[i] - my);
            den += (i - mx) * (i - mx);
        }
        return num / den;
    }
}
