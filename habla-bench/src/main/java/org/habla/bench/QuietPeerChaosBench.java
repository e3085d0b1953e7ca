package org.habla.bench;

import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.config.ConfigLoader;
import org.habla.config.Reconnect;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.habla.testing.NetworkNamespace;

/**
 * A quiet peer whose host vanishes: the docs' teacher terminal ({@code nc -l}) runs in a network namespace of its
 * own, a daemon's {@code text-lines} link reaches it over a veth pair, the teacher types one line and then says
 * nothing; after a random 0-3 s the namespace's link is taken down (a pulled cable: no FIN, no reset). Prints, per
 * trial, how long after the cut the daemon declared the link lost, and the error it gave. The expected bound is
 * the TCP keep-alive's {@code tcpKeepAliveIdleS + tcpKeepAliveCount × tcpKeepAliveIntervalS}. Needs root, {@code ip}
 * and {@code nc}; says why and skips otherwise.
 */
final class QuietPeerChaosBench {

    private final int trials;

    QuietPeerChaosBench(int trials) {
        this.trials = trials;
    }

    void run() throws Exception {
        Reconnect.TcpKeepAlive k = Reconnect.DEFAULTS.tcpKeepAlive();
        System.out.printf("%nquiet peer, host vanishes: %d trials of a silent nc -l behind a veth pair that is cut; "
                + "TCP keep-alive idle %d s, interval %d s, count %d (bound %d s)%n", trials, k.idleS(), k.intervalS(),
                k.count(), k.detectionS());
        String why = NetworkNamespace.unavailable();
        Path nc = findOnPath("nc");
        if (why != null || nc == null) {
            System.out.println("  skipped: " + (why != null ? why : "nc (netcat-openbsd) is not installed"));
            return;
        }
        Random random = new Random(3);
        List<Double> lost = new ArrayList<>();
        System.out.println("  idle before the cut    declared lost after the cut    error");
        for (int i = 0; i < trials; i++) {
            double idleS = 3 * random.nextDouble();
            try (NetworkNamespace ns = NetworkNamespace.create()) {
                int[] ports = DaemonProcess.freePorts(2);
                Process peer = new ProcessBuilder(cat(ns.wrapper(), nc.toString(), "-l", ns.address(),
                        String.valueOf(ports[0]))).redirectErrorStream(true)
                        .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
                try (Daemon daemon = daemon(ns.address(), ports[0], ports[1])) {
                    await(() -> up(daemon), 20_000, "the keyboard link");
                    OutputStream keys = peer.getOutputStream();
                    keys.write("1\n".getBytes(StandardCharsets.UTF_8));
                    keys.flush();
                    await(() -> lines(daemon) >= 1, 10_000, "the typed line");
                    TimeUnit.MILLISECONDS.sleep((long) (idleS * 1000));
                    ns.cutLink();
                    long cut = System.nanoTime();
                    await(() -> !up(daemon), 60_000, "the link declared lost");
                    double afterS = (System.nanoTime() - cut) / 1e9;
                    lost.add(afterS);
                    String error = daemon.status().path("interfaces").get(0).path("connections").get(0)
                            .path("lastError").asText();
                    System.out.printf(Locale.ROOT, "  %17.1f s  %27.2f s    %s%n", idleS, afterS, error);
                } finally {
                    peer.destroy();
                    if (!peer.waitFor(5, TimeUnit.SECONDS)) {
                        peer.destroyForcibly();
                    }
                }
            }
        }
        lost.sort(null);
        System.out.printf(Locale.ROOT, "declared lost after the cut: min %.2f s, median %.2f s, max %.2f s (bound %d s)%n",
                lost.get(0), lost.get(lost.size() / 2), lost.get(lost.size() - 1), k.detectionS());
    }

    private static Daemon daemon(String host, int keyboardPort, int socketPort) throws Exception {
        String json = """
                {"system": "quiet-peer-chaos", "safety": {"watchdogMs": 0}, "status": {"port": 0},
                 "interfaces": [{"id": "keyboard", "driver": "text-lines", "address": "%s:%d"}],
                 "methods": [
                  {"id": "key", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@keyboard.lines"},
                   "params": {"kind": "text"}},
                  {"id": "key-up", "type": "pass-through", "layer": "processing", "inputs": {"in": "key.out"},
                   "params": {"kind": "text"}},
                  {"id": "keys", "type": "pass-through", "layer": "virtual", "inputs": {"in": "key-up.out"},
                   "params": {"kind": "text"}, "expose": {"port": %d, "name": "keys"}}]}
                """.formatted(host, keyboardPort, socketPort);
        PluginRegistry registry = PluginRegistry.discover();
        return Daemon.start(new ConfigLoader(registry).parse(json), registry, EngineClock.system());
    }

    private static boolean up(Daemon daemon) {
        return daemon.status().path("interfaces").get(0).path("up").asBoolean();
    }

    private static long lines(Daemon daemon) {
        return daemon.status().path("interfaces").get(0).path("readings").path("lines").asLong();
    }

    private static List<String> cat(List<String> prefix, String... rest) {
        List<String> all = new ArrayList<>(prefix);
        all.addAll(List.of(rest));
        return all;
    }

    private static Path findOnPath(String name) {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(java.io.File.pathSeparator)) {
            Path p = Path.of(dir, name);
            if (Files.isExecutable(p)) {
                return p;
            }
        }
        return null;
    }

    private static void await(BooleanSupplier condition, long millis, String what) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > end) {
                throw new IllegalStateException("timed out waiting for " + what);
            }
            Thread.sleep(1);
        }
    }
}
