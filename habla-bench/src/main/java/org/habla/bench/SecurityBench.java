package org.habla.bench;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.habla.daemon.Daemon;
import org.habla.security.Tls;

/**
 * Benchmark (security): what authentication and TLS cost a sample, robot stamp to control client, on the latency
 * benchmark's path ({@link LatencyBench}): the socket as it is without security, the same socket with
 * authentication required (plain TCP), and with authentication over TLS (a lab certificate made with
 * {@code openssl}, as docs/security.md says); printed as figures and as ratios to the first.
 */
final class SecurityBench {

    private static final String TOKEN = "bench-token-0123456789abcdef";

    private final LatencyBench latency;

    SecurityBench(int rateHz, int warmupS, int seconds) {
        this.latency = new LatencyBench(rateHz, warmupS, seconds);
    }

    void run() throws Exception {
        Path dir = Files.createTempDirectory("habla-security-bench");
        Path certificate = dir.resolve("lab.crt");
        Path key = dir.resolve("lab.key");
        Process p = new ProcessBuilder("openssl", "req", "-x509", "-newkey", "ec", "-pkeyopt",
                "ec_paramgen_curve:prime256v1", "-nodes", "-keyout", key.toString(), "-out", certificate.toString(),
                "-days", "2", "-subj", "/CN=localhost", "-addext", "subjectAltName=IP:127.0.0.1")
                .redirectErrorStream(true).start();
        String made = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
            throw new IllegalStateException("openssl could not make the lab certificate: " + made);
        }
        Files.writeString(Files.createFile(dir.resolve("bench.credentials.json"),
                PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------"))),
                "{\"clients\": [{\"name\": \"bench\", \"token\": \"" + TOKEN + "\", \"roles\": {\"*\": \"read\"}}]}");
        String security = "{\"credentials\": \"bench.credentials.json\", \"loopback\": \"authenticated\", "
                + "\"tls\": {\"certificate\": \"lab.crt\", \"key\": \"lab.key\"}}";
        String auth = "{\"op\":\"auth\",\"client\":\"bench\",\"token\":\"" + TOKEN + "\"}";
        Tls trust = Tls.client(certificate);

        System.out.printf("%n(security) latency, robot stamp -> control client: no authentication, authentication "
                + "(plain TCP), authentication over TLS%n");
        System.out.printf("%-44s %8s %8s %8s %8s %8s %8s%n", "path", "samples", "lost", "p50 µs", "p99 µs",
                "p99.9 µs", "max µs");
        List<LatencyBench.Figures> open = new ArrayList<>();
        List<LatencyBench.Figures> authenticated = new ArrayList<>();
        List<LatencyBench.Figures> tls = new ArrayList<>();
        // Rounds of the three, interleaved, so that a load that changes over the run weighs on each alike.
        for (int round = 1; round <= ROUNDS; round++) {
            open.add(latency.measure("round " + round + ": no authentication (as before)", robot -> {
                Daemon d = BenchDaemon.start(robot.port());
                return new LatencyBench.Path(d.port("value"), d::close, d);
            }));
            authenticated.add(latency.measure("round " + round + ": authenticated, plain TCP", robot -> {
                Daemon d = BenchDaemon.start(robot.port(), security, false, dir);
                return new LatencyBench.Path(d.port("value"), d::close, d, port ->
                        new SampleClient(new java.net.Socket("127.0.0.1", port), auth));
            }));
            tls.add(latency.measure("round " + round + ": authenticated, TLS", robot -> {
                Daemon d = BenchDaemon.start(robot.port(), security, true, dir);
                return new LatencyBench.Path(d.port("value"), d::close, d, port -> new SampleClient(
                        trust.connect(new java.net.Socket("127.0.0.1", port), "127.0.0.1", port, 10_000), auth));
            }));
        }
        System.out.printf("%nmedians of %d rounds [µs]           %8s %8s %8s%n", ROUNDS, "p50", "p99", "p99.9");
        median("no authentication (as before)", open);
        median("authenticated, plain TCP", authenticated);
        median("authenticated, TLS", tls);
        System.out.printf("ratios of the medians to no authentication %8s %8s %8s%n", "p50", "p99", "p99.9");
        ratio("authenticated, plain TCP", authenticated, open);
        ratio("authenticated, TLS", tls, open);
    }

    /** Interleaved rounds of the three paths. */
    private static final int ROUNDS = 3;

    private static long median(List<LatencyBench.Figures> fs, java.util.function.ToLongFunction<LatencyBench.Figures> f) {
        long[] v = fs.stream().mapToLong(f).sorted().toArray();
        return v[v.length / 2];
    }

    private static void median(String name, List<LatencyBench.Figures> fs) {
        System.out.printf(Locale.ROOT, "%-38s %8d %8d %8d%n", name, median(fs, LatencyBench.Figures::p50),
                median(fs, LatencyBench.Figures::p99), median(fs, LatencyBench.Figures::p999));
    }

    private static void ratio(String name, List<LatencyBench.Figures> fs, List<LatencyBench.Figures> base) {
        System.out.printf(Locale.ROOT, "%-42s %8.2f %8.2f %8.2f%n", name,
                (double) median(fs, LatencyBench.Figures::p50) / Math.max(1, median(base, LatencyBench.Figures::p50)),
                (double) median(fs, LatencyBench.Figures::p99) / Math.max(1, median(base, LatencyBench.Figures::p99)),
                (double) median(fs, LatencyBench.Figures::p999) / Math.max(1, median(base, LatencyBench.Figures::p999)));
    }
}
