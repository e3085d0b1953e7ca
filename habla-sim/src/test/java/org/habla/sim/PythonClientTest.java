package org.habla.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Runs the tests of the packaged Python client, {@code clients/python} (pytest), so the build breaks when the
 * client does: its framing and errors against a scripted peer, then authentication, TLS, actions, staleness
 * and reconnection against a real daemon with config/pioneer.json and the simulated Pioneer, both started by
 * the tests with this build's classes.
 */
@Timeout(300)
class PythonClientTest {

    private static final Path CLIENT = Paths.get("..", "clients", "python").toAbsolutePath().normalize();

    @Test
    void thePackagedClientPassesItsOwnTests(@TempDir Path tmp) throws Exception {
        PytestRun run = PytestRun.of(List.of("python3"), CLIENT, tmp).start(CLIENT.resolve("tests"));
        assertThat(run.finished()).as("pytest finished within %d s:%n%s", PytestRun.LIMIT_S, run.log()).isTrue();
        assertThat(run.exitCode()).as("pytest in %s:%n%s", CLIENT, run.log()).isZero();
        assertThat(run.log()).containsPattern("\\d+ passed").doesNotContain(" skipped");
    }
}
