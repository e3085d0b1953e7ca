package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The launcher's class cache (.mvn/class-cache.sh): which JVM options a daemon gets on each JDK, and that a cache
 * is recorded, made and used, and that one that no longer fits never stops a start.
 */
class LauncherClassCacheTest {

    private static final Path SCRIPTS = Path.of("..", ".mvn").toAbsolutePath().normalize();
    private static final long WAIT_MS = 60_000;

    @Test
    void aJdkBefore24GetsTheClassDataArchiveTheJvmKeepsItself(@TempDir Path tmp) throws Exception {
        Path jdk = fakeJdk(tmp, "21.0.5");
        Path cds = tmp.resolve("cds");
        assertThat(options(jdk, cds, tmp.resolve("lib"))).containsExactly("-XX:+AutoCreateSharedArchive",
                "-XX:SharedArchiveFile=" + cds.resolve("run.jsa"), "-Xlog:cds*=off");
    }

    @Test
    void onJdk24AndLaterTheFirstDaemonRecordsTheNextMakesTheCacheAndTheOnesAfterMapIt(@TempDir Path tmp)
            throws Exception {
        Path jdk = fakeJdk(tmp, "25.0.1");
        Path cds = tmp.resolve("cds");
        Path lib = Files.createDirectories(tmp.resolve("lib"));
        Path edge = Files.createDirectories(lib.resolve("edge"));
        for (Path jar : List.of(lib.resolve("a.jar"), edge.resolve("b.jar"))) {
            Files.writeString(jar, "");
            Files.setLastModifiedTime(jar, FileTime.fromMillis(System.currentTimeMillis() - 60_000));
        }
        String cp = lib + "/*:" + edge + "/*";

        List<String> first = classPathOptions(jdk, cds, cp);
        assertThat(first.get(0)).isEqualTo("-XX:AOTMode=record");
        Path recording = Path.of(first.get(1).substring("-XX:AOTConfiguration=".length()));
        assertThat(recording.getFileName().toString()).matches("run-\\d+\\.\\d+\\.aotconf");
        // The recording daemon has stopped (its PID is that of the shell, gone): the next launch makes the cache.
        Files.writeString(recording, "recorded");

        assertThat(classPathOptions(jdk, cds, cp)).isEmpty();
        Path cache = awaitCache(cds);
        assertThat(Files.readString(cache)).isEqualTo("made from recorded");
        assertThat(classPathOptions(jdk, cds, cp))
                .containsExactly("-XX:AOTCache=" + cache, "-Xlog:aot*=off", "-Xlog:cds*=off");

        // A jar newer than the cache, in any folder of the class path: the cache is deleted and a daemon records again.
        Files.setLastModifiedTime(edge.resolve("b.jar"), FileTime.fromMillis(System.currentTimeMillis() + 60_000));
        assertThat(classPathOptions(jdk, cds, cp).get(0)).isEqualTo("-XX:AOTMode=record");
        assertThat(cache).doesNotExist();
    }

    @Test
    void otherJvmOptionsKeepACacheOfTheirOwn(@TempDir Path tmp) throws Exception {
        Path jdk = fakeJdk(tmp, "25.0.1");
        Path cds = tmp.resolve("cds");
        String a = options(jdk, cds, tmp, "-Xmx256m").get(1);
        String b = options(jdk, cds, tmp, "-Xmx512m").get(1);
        assertThat(a.substring(0, a.indexOf('.'))).isNotEqualTo(b.substring(0, b.indexOf('.')));
    }

    @Test
    void aDaemonWithAFlightRecordingRecordsNoCacheSinceTheJvmWouldTurnTheRecordingOff(@TempDir Path tmp)
            throws Exception {
        Path jdk = fakeJdk(tmp, "25.0.1");
        Path cds = tmp.resolve("cds");
        assertThat(options(jdk, cds, tmp, "-Xmx256m", "-XX:StartFlightRecording=duration=60s,filename=d.jfr")).isEmpty();
        assertThat(options(jdk, cds, tmp, "-Xmx256m").get(0)).isEqualTo("-XX:AOTMode=record");
    }

    @Test
    void withThisJdkARecordedCacheIsUsedAndOneThatNoLongerFitsStillStartsSilently(@TempDir Path tmp)
            throws Exception {
        Path jdk = Path.of(System.getProperty("java.home"));
        assumeTrue(Runtime.version().feature() >= 24, "the ahead-of-time cache needs JDK 24 or later");
        Path cds = tmp.resolve("cds");
        Path lib = Files.createDirectories(tmp.resolve("lib"));
        writeHelloJar(lib.resolve("hello.jar"), tmp.resolve("src"));

        // The recording JVM says where it wrote, when it stops.
        assertThat(launch(jdk, cds, lib)).startsWith("hello\n");
        try (Stream<Path> files = Files.list(cds)) {
            assertThat(files.map(p -> p.getFileName().toString())).anyMatch(n -> n.endsWith(".aotconf"));
        }
        assertThat(launch(jdk, cds, lib)).isEqualTo("hello\n");
        Path cache = awaitCache(cds);
        assertThat(launch(jdk, cds, lib)).isEqualTo("hello\n");

        // The jar rebuilt but with an old time stamp: the launcher cannot tell, the JVM refuses the cache quietly.
        FileTime old = FileTime.from(Files.getLastModifiedTime(cache).toInstant().minusSeconds(3600));
        writeHelloJar(lib.resolve("hello.jar"), tmp.resolve("src2"));
        Files.setLastModifiedTime(lib.resolve("hello.jar"), old);
        assertThat(cache).exists();
        assertThat(launch(jdk, cds, lib)).isEqualTo("hello\n");
    }

    /** The options the launcher's function gives a daemon {@code run} whose jars are in {@code lib}. */
    private static List<String> options(Path jdk, Path cds, Path lib, String... jvmOptions) throws Exception {
        return classPathOptions(jdk, cds, lib + "/*", jvmOptions);
    }

    /** The options the launcher's function gives a daemon {@code run} of class path {@code cp}, one per line. */
    private static List<String> classPathOptions(Path jdk, Path cds, String cp, String... jvmOptions)
            throws Exception {
        String out = bash(jdk, "habla_class_cache '" + cds + "' run '" + cp + "' '" + String.join(" ", jvmOptions)
                + "'; printf '%s\\n' ${habla_cache_opts[@]+\"${habla_cache_opts[@]}\"}");
        return out.isEmpty() ? List.of() : List.of(out.split("\n"));
    }

    /** Runs the hello jar as the launcher runs a daemon; its standard output and error together. */
    private static String launch(Path jdk, Path cds, Path lib) throws Exception {
        return bash(jdk, "habla_class_cache '" + cds + "' run '" + lib + "/*' ''; exec \"$JAVA_HOME/bin/java\" "
                + "${habla_cache_opts[@]+\"${habla_cache_opts[@]}\"} -cp '" + lib + "/*' Hello");
    }

    private static String bash(Path jdk, String script) throws Exception {
        ProcessBuilder pb = new ProcessBuilder("bash", "-c", "set -euo pipefail; . '" + SCRIPTS.resolve("find-jdk.sh")
                + "'; . '" + SCRIPTS.resolve("class-cache.sh") + "'; " + script).redirectErrorStream(true);
        pb.environment().put("JAVA_HOME", jdk.toString());
        // The cache is made at the lowest priority; beside busy processes it would wait for minutes. What is tested
        // here is that it is made and used, so it is made at the priority of the processes around it.
        pb.environment().put("HABLA_CACHE_NICE", "0");
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(WAIT_MS, TimeUnit.MILLISECONDS)).as(out).isTrue();
        assertThat(p.exitValue()).as(out).isZero();
        return out;
    }

    /** The cache the background maker writes, once it is there. */
    private static Path awaitCache(Path cds) throws Exception {
        long end = System.currentTimeMillis() + WAIT_MS;
        while (System.currentTimeMillis() < end) {
            try (Stream<Path> files = Files.list(cds)) {
                List<Path> made = files.filter(p -> p.getFileName().toString().matches("run-\\d+\\.aot")).toList();
                if (!made.isEmpty()) {
                    return made.get(0);
                }
            }
            Thread.sleep(50);
        }
        throw new AssertionError("no cache was made in " + cds + " within " + WAIT_MS + " ms");
    }

    /** A JDK home with a release file and a java that "makes" a cache by writing what it was given into it. */
    private static Path fakeJdk(Path tmp, String version) throws IOException {
        Path home = Files.createDirectories(tmp.resolve("jdk-" + version));
        Files.writeString(home.resolve("release"), "JAVA_VERSION=\"" + version + "\"\n");
        Path java = Files.createDirectories(home.resolve("bin")).resolve("java");
        Files.writeString(java, """
                #!/usr/bin/env bash
                for a in "$@"; do
                  case $a in
                    -XX:AOTConfiguration=*) conf=${a#*=} ;;
                    -XX:AOTCache=*) cache=${a#*=} ;;
                  esac
                done
                printf 'made from %s' "$(cat "$conf")" > "$cache"
                """);
        java.toFile().setExecutable(true);
        return home;
    }

    private static void writeHelloJar(Path jar, Path src) throws IOException {
        Files.createDirectories(src);
        Files.writeString(src.resolve("Hello.java"),
                "public class Hello { public static void main(String[] a) { System.out.println(\"hello\"); } }");
        assertThat(ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", src.toString(),
                src.resolve("Hello.java").toString())).isZero();
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            out.putNextEntry(new JarEntry("Hello.class"));
            out.write(Files.readAllBytes(src.resolve("Hello.class")));
            out.closeEntry();
        }
    }
}
