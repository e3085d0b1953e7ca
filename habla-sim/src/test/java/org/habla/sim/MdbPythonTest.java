package org.habla.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Runs the Python tests of the MDB control architecture in {@code examples/mdb} (its models, its evolution,
 * and seeded end-to-end episodes against its fake world over loopback), so a change that breaks the example
 * breaks the build. Skipped, saying so, only where no {@code python3} is installed.
 */
@Timeout(660)
class MdbPythonTest {

    private static final Path MDB = Paths.get("..", "examples", "mdb").toAbsolutePath().normalize();
    /**
     * A bound on the whole unittest run, not a speed check: about 90 s of CPU-bound simulation on a quiet machine,
     * several times that on two cores shared with a build and busy processes.
     */
    private static final long LIMIT_S = 600;

    @Test
    void theMdbExamplePassesItsOwnTests(@TempDir Path tmp) throws Exception {
        Assumptions.assumeTrue(python3Present(), "python3 is not installed: the MDB example's tests cannot run");
        assertThat(MDB.resolve("test_mdb.py")).exists();
        Path out = tmp.resolve("unittest.log");
        ProcessBuilder pb = new ProcessBuilder("python3", "-m", "unittest", "-v").directory(MDB.toFile())
                .redirectErrorStream(true).redirectOutput(out.toFile());
        pb.environment().put("PYTHONDONTWRITEBYTECODE", "1");
        Process p = pb.start();
        boolean finished = p.waitFor(LIMIT_S, TimeUnit.SECONDS);
        if (!finished) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        }
        String log = Files.readString(out, StandardCharsets.UTF_8);
        assertThat(finished).as("python3 -m unittest finished within %d s:%n%s", LIMIT_S, log).isTrue();
        assertThat(p.exitValue()).as("python3 -m unittest in %s:%n%s", MDB, log).isZero();
        assertThat(log).contains("OK").contains("episodes reached the object after the teacher left");
    }

    private static boolean python3Present() throws InterruptedException {
        try {
            Process p = new ProcessBuilder("python3", "--version").redirectErrorStream(true).start();
            return p.waitFor(20, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        }
    }
}
