package org.habla.bench;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.habla.net.Frame;
import org.habla.net.FrameReader;
import org.habla.net.FrameWriter;

/**
 * Chaos (a), hostile and careless clients: the simulated Pioneer and {@code habla run} in processes of their
 * own; a good client writes the action socket and reads {@code distance_angle} at 10 Hz; then a thousand
 * hostile connections of every kind ({@link HostileCrowd}) arrive at once, a third of them on the action
 * socket, the rest over the other control sockets and the status endpoint. Prints the good client's answer
 * times and errors before, during and after; how long a good newcomer waited to be served in the middle of
 * the burst; how every hostile connection ended (those that read what they are sent — idle, and the holders once
 * they look — are readers, which the daemon keeps: they end "open"); the daemon's resident memory and threads before, at their
 * highest, after, and after a full collection (what it could give back), and the most bytes it held for
 * blocks in flight (its own count).
 */
final class HostileClientsBench {

    /**
     * The daemon runs with this idle deadline (instead of 5 min) so that connections that stop taking what they are
     * sent end within the run. Connections that read what they are sent are readers and stay.
     */
    static final long IDLE_TIMEOUT_MS = 20_000;

    private final int hostile;
    private final int attackSeconds;

    HostileClientsBench(int hostile, int attackSeconds) {
        this.hostile = hostile;
        this.attackSeconds = attackSeconds;
    }

    void run() throws Exception {
        System.out.printf("%n(chaos) hostile and careless clients: %d connections at once against the Pioneer daemon"
                + " (own process; limits.idleTimeoutMs=%d, the other limits at their defaults), %d s of attack%n",
                hostile, IDLE_TIMEOUT_MS, attackSeconds);
        try (PioneerRig rig = new PioneerRig(root -> root.with("limits").put("idleTimeoutMs", IDLE_TIMEOUT_MS))) {
            rig.start();
            int action = rig.port("action");
            try (SteadyClient good = new SteadyClient(action, rig.port("distance_angle"))) {
                Thread.sleep(10_000); // warm-up
                good.take();
                Thread.sleep(20_000);
                SteadyClient.Window before = good.take();
                PioneerRig.ProcessFigures figuresBefore = rig.figures();

                List<Integer> targets = new ArrayList<>(List.of(action, action, action));
                rig.controlPorts().stream().filter(p -> p != action).forEach(targets::add);
                targets.add(rig.statusPort());
                double peakRss = figuresBefore.rssMb();
                int peakThreads = figuresBefore.threads();
                long peakBlocks = 0;
                long statusFailures = 0;
                String newcomer;
                try (HostileCrowd crowd = new HostileCrowd()) {
                    crowd.launch(hostile, targets, 9);
                    Thread.sleep(500);
                    newcomer = newcomer(action);
                    for (int s = 0; s < attackSeconds; s++) {
                        Thread.sleep(1_000);
                        PioneerRig.ProcessFigures f = rig.figures();
                        peakRss = Math.max(peakRss, f.rssMb());
                        peakThreads = Math.max(peakThreads, f.threads());
                        try {
                            peakBlocks = Math.max(peakBlocks, rig.status().path("blocks").path("bytesInFlight").asLong());
                        } catch (IOException e) {
                            statusFailures++;
                        }
                    }
                    SteadyClient.Window during = good.take();
                    crowd.startReading(); // and wait (at most 60 s) until the daemon has ended every one
                    long end = System.nanoTime() + 60_000_000_000L;
                    while (crowd.ended() < hostile && System.nanoTime() < end) {
                        Thread.sleep(200);
                        peakRss = Math.max(peakRss, rig.figures().rssMb());
                    }
                    crowd.close(); // what is still open now is counted as open
                    Map<HostileCrowd.Kind, Map<HostileCrowd.Outcome, Integer>> outcomes = crowd.outcomes();
                    good.take();
                    Thread.sleep(10_000);
                    SteadyClient.Window after = good.take();
                    PioneerRig.ProcessFigures figuresAfter = rig.figures();
                    JsonNode sockets = rig.status().path("sockets");
                    rig.fullGc();
                    Thread.sleep(2_000);
                    PioneerRig.ProcessFigures figuresCollected = rig.figures();

                    System.out.printf("%-28s %8s %8s %8s %8s %8s %9s%n", "good client (10 Hz)", "writes", "errors",
                            "p50 ms", "p99 ms", "max ms", "samples");
                    print("before the attack (20 s)", before);
                    print("during the attack (" + attackSeconds + " s)", during);
                    print("after it (10 s)", after);
                    System.out.println("a good newcomer on the action socket, 0.5 s into the burst: " + newcomer);
                    System.out.printf("%-14s %9s %9s %9s%n", "hostile kind", "answered", "closed", "open");
                    outcomes.forEach((k, o) -> System.out.printf("%-14s %9d %9d %9d%n", k.name().toLowerCase(),
                            o.get(HostileCrowd.Outcome.ANSWERED), o.get(HostileCrowd.Outcome.CLOSED),
                            o.get(HostileCrowd.Outcome.OPEN)));
                    long evicted = 0;
                    long timeouts = 0;
                    for (JsonNode s : sockets) {
                        evicted += s.path("evicted").asLong();
                        timeouts += s.path("idleTimeouts").asLong() + s.path("frameTimeouts").asLong();
                    }
                    System.out.printf("the daemon's control sockets: %d evicted, %d closed on a deadline%n", evicted,
                            timeouts);
                    System.out.printf("daemon RSS: %.0f MB before, %.0f MB at most, %.0f MB after (growth at most"
                            + " %.0f MB), %.0f MB after a full GC; threads %d before, %d at most, %d after%n",
                            figuresBefore.rssMb(), peakRss, figuresAfter.rssMb(), peakRss - figuresBefore.rssMb(),
                            figuresCollected.rssMb(), figuresBefore.threads(), peakThreads, figuresAfter.threads());
                    System.out.printf("bytes held for blocks in flight (the daemon's count), at most: %d (budget %d);"
                            + " status reads that failed during the attack: %d%n", peakBlocks,
                            rig.status().path("blocks").path("budgetBytes").asLong(), statusFailures);
                }
            }
        }
    }

    private static void print(String phase, SteadyClient.Window w) {
        System.out.printf("%-28s %8d %8d %8.2f %8.2f %8.1f %9d%n", phase, w.writes(), w.errors(), w.p50Ms(), w.p99Ms(),
                w.maxMs(), w.samples());
    }

    /** Connects a fresh client and times it from connect to its first answer, or says what went wrong. */
    private static String newcomer(int port) {
        long start = System.nanoTime();
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress("127.0.0.1", port), 30_000);
            s.setSoTimeout(30_000);
            FrameReader in = new FrameReader(new BufferedInputStream(s.getInputStream()), 1 << 20, 1 << 24);
            ObjectNode ping = JsonNodeFactory.instance.objectNode().put("op", "ping").put("id", "newcomer");
            new FrameWriter(s.getOutputStream()).send(ping);
            for (Frame f = in.read(); f != null; f = in.read()) {
                if (f.type().equals("pong")) {
                    return String.format("served in %.1f ms", (System.nanoTime() - start) / 1e6);
                }
                if (f.type().equals("error")) {
                    return "refused: " + f.header();
                }
            }
            return "closed without an answer";
        } catch (IOException e) {
            return "failed: " + e;
        }
    }
}
