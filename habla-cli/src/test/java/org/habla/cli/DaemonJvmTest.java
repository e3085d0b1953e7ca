package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class DaemonJvmTest {

    @Test
    void aDaemonTakesTheOptionsOfItsHomesFileAndOtherCommandsTakeNone(@TempDir Path home) throws Exception {
        assumeTrue(System.getenv("HABLA_JAVA_OPTS") == null, "HABLA_JAVA_OPTS replaces the file");
        Files.createDirectories(home.resolve("config"));
        Files.writeString(home.resolve(DaemonJvm.OPTIONS_FILE), "  -XX:+UseSerialGC   -Xmn16m\n");
        assertThat(DaemonJvm.options(home, "run")).containsExactly("-XX:+UseSerialGC", "-Xmn16m");
        assertThat(DaemonJvm.options(home, "worker")).containsExactly("-XX:+UseSerialGC", "-Xmn16m");
        assertThat(DaemonJvm.options(home, "check")).isEmpty();
        assertThat(DaemonJvm.options(home.resolve("elsewhere"), "run")).isEmpty();
    }

    @Test
    void theProjectsOwnFileNamesOptionsTheJvmAccepts() throws Exception {
        Path file = Path.of("..").resolve(DaemonJvm.OPTIONS_FILE);
        assertThat(file).isRegularFile();
        var cmd = new java.util.ArrayList<>(java.util.List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(DaemonJvm.split(Files.readString(file)));
        cmd.add("-version");
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes());
        assertThat(p.waitFor()).as(out).isZero();
    }
}
