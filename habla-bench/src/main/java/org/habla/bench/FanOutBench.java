package org.habla.bench;

import com.fasterxml.jackson.databind.JsonNode;
import java.net.InetAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import org.HdrHistogram.Histogram;
import org.habla.daemon.Daemon;

/**
 * Benchmark (c): one exposed method, ten control clients on its socket. The robot streams at a fixed
 * rate through the same chain as benchmark (a); each client counts samples, sequence gaps and latency;
 * the daemon's socket figures give what its per-client queues dropped. A last round adds an eleventh
 * client that connects and never reads, to show that it alone loses samples; then {@link FanOutCrowd}'s round
 * of 200 readers at 100 Hz.
 */
final class FanOutBench {

    private static final int CLIENTS = 10;

    private final int warmupS;
    private final int seconds;

    FanOutBench(int warmupS, int seconds) {
        this.warmupS = warmupS;
        this.seconds = seconds;
    }

    void run() throws Exception {
        System.out.printf("%n(c) fan-out: %d clients on one exposed method, %d s warm-up, %d s measured%n",
                CLIENTS, warmupS, seconds);
        System.out.printf("%-34s %10s %12s %10s %10s %8s %8s%n", "case", "robot Hz", "samples/s", "min/client",
                "lost", "p50 µs", "p99 µs");
        for (int rateHz : new int[] {1_000, 5_000}) {
            round(rateHz, false);
        }
        round(5_000, true);
        new FanOutCrowd(200, 100, warmupS, seconds, false).run();
    }

    private void round(int rateHz, boolean stalled) throws Exception {
        try (BenchRobot robot = new BenchRobot(1_000_000_000L / rateHz)) {
            Daemon daemon = BenchDaemon.start(robot.port());
            List<SampleClient> clients = new ArrayList<>();
            Socket silent = null;
            try {
                int port = daemon.port("value");
                for (int i = 0; i < CLIENTS; i++) {
                    clients.add(new SampleClient(port));
                }
                if (stalled) {
                    silent = new Socket();
                    silent.setReceiveBufferSize(4096);
                    silent.connect(new java.net.InetSocketAddress(InetAddress.getLoopbackAddress(), port));
                }
                for (SampleClient c : clients) {
                    LatencyBench.await(() -> c.total() > 0, 20_000, "no sample reached a fan-out client");
                }
                Thread.sleep(warmupS * 1000L);
                long droppedBefore = dropped(daemon);
                clients.forEach(SampleClient::startRecording);
                long t0 = System.nanoTime();
                Thread.sleep(seconds * 1000L);
                clients.forEach(SampleClient::stopRecording);
                double s = (System.nanoTime() - t0) / 1e9;
                long total = 0;
                long min = Long.MAX_VALUE;
                long lost = 0;
                Histogram all = new Histogram(60_000_000L, 3);
                for (SampleClient c : clients) {
                    total += c.samples();
                    min = Math.min(min, c.samples());
                    lost += c.missing();
                    all.add(c.latencyMicros());
                }
                String name = stalled ? CLIENTS + " readers + 1 that never reads" : CLIENTS + " readers";
                System.out.printf("%-34s %10d %,12.0f %,10.0f %10d %8d %8d%n", name, rateHz, total / s, min / s, lost,
                        all.getValueAtPercentile(50), all.getValueAtPercentile(99));
                System.out.printf("  daemon socket: %d samples dropped from client queues while measuring%s%n",
                        dropped(daemon) - droppedBefore, stalled ? "; of them the readers lost " + lost
                                + ", the silent client the rest" : "");
            } finally {
                for (SampleClient c : clients) {
                    c.close();
                }
                if (silent != null) {
                    silent.close();
                }
                daemon.close();
            }
        }
    }

    /** Samples the daemon's socket {@code value} has dropped from its client queues so far. */
    static long dropped(Daemon daemon) {
        for (JsonNode s : daemon.status().path("sockets")) {
            if ("value".equals(s.path("socket").asText())) {
                return s.path("dropped").asLong();
            }
        }
        return 0;
    }
}
