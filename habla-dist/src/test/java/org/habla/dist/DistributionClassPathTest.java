package org.habla.dist;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.habla.testing.DaemonProcess;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The distribution this build made, run through the launcher as a user runs it: a worker's class path is lib/ alone,
 * with no Jetty and no zstd (the monitor and the recording are lib/edge/'s), and a daemon's has both and serves its
 * monitor.
 */
class DistributionClassPathTest {

    private static final Path ROOT = Path.of("..").toAbsolutePath().normalize();
    private static final Path LIB = ROOT.resolve("habla-dist/target/lib");
    private static final Path EDGE = LIB.resolve("edge");
    /** The jars only the products beside a daemon need. */
    private static final Pattern EDGE_JAR = Pattern.compile("(habla-monitor|habla-recording|jetty-|zstd-jni).*\\.jar");
    private static final long START_MS = DaemonProcess.START_MS;

    @Test
    void libHoldsTheEngineAndLibEdgeTheMonitorTheRecordingJettyAndZstd() throws IOException {
        assertThat(jars(LIB)).contains(jar(LIB, "habla-core"), jar(LIB, "habla-cli"), jar(LIB, "habla-methods"),
                jar(LIB, "habla-drivers"), jar(LIB, "picocli"));
        assertThat(jars(LIB)).noneMatch(j -> EDGE_JAR.matcher(j).matches());
        assertThat(jars(EDGE)).allMatch(j -> EDGE_JAR.matcher(j).matches())
                .contains(jar(EDGE, "habla-monitor"), jar(EDGE, "jetty-server"), jar(EDGE, "zstd-jni"));
    }

    @Test
    void theLauncherRunsAWorkerOnLibAloneAndItListens() throws Exception {
        Process worker = launch(null, "worker", "--bind", "127.0.0.1", "--port", "0");
        try {
            assertThat(firstLineWith(worker, "HABLA worker on 127.0.0.1:")).isNotNull();
            assertThat(classPath(worker)).isEqualTo(LIB + "/*");
        } finally {
            stop(worker);
        }
    }

    @Test
    void theLauncherRunsADaemonOnLibAndLibEdgeAndItServesItsMonitor(@TempDir Path dir) throws Exception {
        int[] ports = DaemonProcess.freePorts(3);
        Path config = Files.writeString(dir.resolve("watched.json"), """
                {"system": "watched", "safety": {"watchdogMs": 0},
                 "status": {"port": %d, "monitorPort": %d},
                 "methods": [{"id": "cmd", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
                              "params": {"kind": "number"}, "expose": {"port": %d}}]}
                """.formatted(ports[0], ports[1], ports[2]));
        Process daemon = launch(dir.resolve("daemon.log"), "run", config.toString());
        try {
            assertThat(DaemonProcess.awaitPort(ports[2], START_MS)).as("the daemon's control socket; %s",
                    Files.readString(dir.resolve("daemon.log"))).isTrue();
            assertThat(classPath(daemon)).isEqualTo(LIB + "/*:" + EDGE + "/*");
            HttpResponse<String> page = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                    URI.create("http://127.0.0.1:" + ports[1] + "/")).timeout(Duration.ofSeconds(30)).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertThat(page.statusCode()).isEqualTo(200);
            assertThat(page.body()).contains("<html");
        } finally {
            stop(daemon);
        }
    }

    /**
     * Starts {@code ./habla args...} without the class cache, its output to {@code log} (null: a pipe). The launcher
     * builds the distribution when its stamp is older than the sources; this build has just made it, so the stamp is
     * set to now first.
     */
    private static Process launch(Path log, String... args) throws IOException {
        assumeTrue(Files.isDirectory(EDGE), "no distribution: run the build's package phase first");
        Path stamp = ROOT.resolve("habla-dist/target/.built");
        if (!Files.exists(stamp)) {
            Files.createFile(stamp);
        }
        Files.setLastModifiedTime(stamp, FileTime.fromMillis(System.currentTimeMillis()));
        ProcessBuilder pb = new ProcessBuilder(Stream.concat(Stream.of(ROOT.resolve("habla").toString()),
                Stream.of(args)).toList()).redirectErrorStream(true);
        if (log != null) {
            pb.redirectOutput(log.toFile());
        }
        pb.environment().put("HABLA_CDS", "off");
        pb.environment().put("HABLA_JAVA_OPTS", "-Xmx256m");
        return pb.start();
    }

    /** The value of the -cp option of the process's JVM (the launcher execs it, so it is the same process). */
    private static String classPath(Process p) throws IOException {
        List<String> args = List.of(new String(Files.readAllBytes(Path.of("/proc", "" + p.pid(), "cmdline")),
                StandardCharsets.UTF_8).split("\0"));
        int i = args.indexOf("-cp");
        assertThat(i).as("the JVM's arguments %s", args).isNotNegative();
        return args.get(i + 1);
    }

    /** The first line of the process's output that starts with {@code prefix}, or null once it ends or after a while. */
    private static String firstLineWith(Process p, String prefix) throws Exception {
        CompletableFuture<String> line = CompletableFuture.supplyAsync(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String l = r.readLine(); l != null; l = r.readLine()) {
                    if (l.startsWith(prefix)) {
                        return l;
                    }
                }
                return null;
            } catch (IOException e) {
                return null;
            }
        });
        return line.get(START_MS, TimeUnit.MILLISECONDS);
    }

    private static void stop(Process p) throws InterruptedException {
        p.destroy();
        if (!p.waitFor(30, TimeUnit.SECONDS)) {
            p.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
        }
    }

    private static List<String> jars(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(f -> f.getFileName().toString()).filter(n -> n.endsWith(".jar")).sorted().toList();
        }
    }

    /** The jar of {@code folder} whose name starts with {@code artifact-} and a version. */
    private static String jar(Path folder, String artifact) throws IOException {
        return jars(folder).stream().filter(j -> j.matches(Pattern.quote(artifact) + "-\\d.*\\.jar")).findFirst()
                .orElse(artifact + " (missing)");
    }
}
