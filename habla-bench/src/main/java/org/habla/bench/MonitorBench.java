package org.habla.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import org.habla.sim.monitor.Browser;

/**
 * Benchmark (f): what the live monitor costs the 1 kHz chain of {@link LatencyBench}: the same daemon without a
 * monitor, with the monitor on and nobody looking, and with a headless Chromium tab open on the monitor showing
 * the chain's 1 kHz output (its last value and scrolling plot). The three are run in turn, {@code rounds} times,
 * so a change in the machine's load falls on all of them.
 */
final class MonitorBench {

    private final LatencyBench latency;
    private final int rounds;

    MonitorBench(int warmupS, int seconds, int rounds) {
        this.latency = new LatencyBench(1_000, warmupS, seconds);
        this.rounds = rounds;
    }

    void run() throws Exception {
        System.out.printf("%n(f) the monitor's cost to the 1 kHz chain (as (a)), %d rounds%n", rounds);
        System.out.printf("%-44s %8s %8s %8s %8s %8s %8s%n", "path", "samples", "lost", "p50 µs", "p99 µs",
                "p99.9 µs", "max µs");
        for (int r = 0; r < rounds; r++) {
            latency.measure("daemon, no monitor", robot -> {
                var d = BenchDaemon.start(robot.port(), null, false);
                return new LatencyBench.Path(d.port("value"), d::close, d);
            });
            latency.measure("daemon, monitor on, no page open", robot -> {
                var d = BenchDaemon.start(robot.port(), null, true);
                return new LatencyBench.Path(d.port("value"), d::close, d);
            });
            latency.measure("daemon, a Chromium tab plotting the output", robot -> {
                var d = BenchDaemon.start(robot.port(), null, true);
                return new LatencyBench.Path(d.port("value"), d::close, d);
            }, path -> {
                Path profile = Files.createTempDirectory("habla-bench-chromium");
                Browser b = new Browser(profile);
                b.open("http://127.0.0.1:" + path.daemon().extensionPort(org.habla.daemon.Daemon.MONITOR) + "/");
                Browser.await("the page shows the graph", 20_000, () -> b.jsLong(
                        "return document.querySelectorAll('#graph g.node[id^=\"method:\"]').length") == 3);
                b.js("document.getElementById('method:v').dispatchEvent(new MouseEvent('click'))");
                Browser.await("the page plots the 1 kHz output", 20_000, () -> b.jsLong(
                        "const p = window.hablaMonitor.plots['v.out']; return p ? p.data[0].length : 0") > 100);
                return b;
            });
        }
    }
}
