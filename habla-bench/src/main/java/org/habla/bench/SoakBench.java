package org.habla.bench;

/**
 * Chaos (b), a long run: the simulated Pioneer and {@code habla run} in processes of their own, a good client
 * at 10 Hz, and every 10 s a small crowd of hostile connections ({@link HostileCrowd}, 25 of every kind
 * spread over the control sockets), for {@code minutes} minutes. Prints, each minute, the daemon's resident
 * memory and thread count and the good client's answer times and errors, so a leak shows as a trend.
 */
final class SoakBench {

    private final int minutes;

    SoakBench(int minutes) {
        this.minutes = minutes;
    }

    void run() throws Exception {
        System.out.printf("%n(chaos) a long run: %d min of the Pioneer daemon (own process; limits.idleTimeoutMs=%d), a"
                + " good client at 10 Hz, 25 hostile connections every 10 s%n", minutes, HostileClientsBench.IDLE_TIMEOUT_MS);
        try (PioneerRig rig = new PioneerRig(root -> root.with("limits")
                .put("idleTimeoutMs", HostileClientsBench.IDLE_TIMEOUT_MS))) {
            rig.start();
            try (SteadyClient good = new SteadyClient(rig.port("action"), rig.port("distance_angle"));
                    HostileCrowd crowd = new HostileCrowd()) {
                Thread.sleep(10_000);
                good.take();
                System.out.printf("%6s %8s %8s %8s %8s %8s %8s %9s%n", "minute", "RSS MB", "threads", "writes", "errors",
                        "p50 ms", "p99 ms", "hostile");
                PioneerRig.ProcessFigures start = rig.figures();
                System.out.printf("%6d %8.0f %8d%n", 0, start.rssMb(), start.threads());
                PioneerRig.ProcessFigures last = start;
                int launched = 0;
                for (int m = 1; m <= minutes; m++) {
                    for (int tick = 0; tick < 6; tick++) {
                        crowd.launch(25, rig.controlPorts(), launched);
                        launched += 25;
                        Thread.sleep(10_000);
                    }
                    crowd.startReading();
                    last = rig.figures();
                    SteadyClient.Window w = good.take();
                    System.out.printf("%6d %8.0f %8d %8d %8d %8.2f %8.2f %9d%n", m, last.rssMb(), last.threads(), w.writes(),
                            w.errors(), w.p50Ms(), w.p99Ms(), launched);
                    if (!rig.daemonAlive()) {
                        System.out.println("the daemon died; see " + rig.dir.resolve("daemon.log"));
                        return;
                    }
                }
                System.out.printf("RSS %.0f -> %.0f MB, threads %d -> %d over %d min; hostile connections ended: %d of %d%n",
                        start.rssMb(), last.rssMb(), start.threads(), last.threads(), minutes, crowd.ended(), launched);
            }
        }
    }
}
