package org.habla.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Runs the tests of {@code clients/python-ros2} (pytest, with real rclpy nodes in the ROS 2 environment that
 * {@code ./habla ros2 setup} makes): the face against a daemon with config/pioneer.json and the simulated
 * Pioneer, the body against the simulated ROS 2 base. Each run keeps its DDS traffic on this machine, in a ROS
 * domain of its own. Without the ROS 2 environment this test fails, naming the command that makes it.
 */
@Timeout(420)
class Ros2PythonTest {

    private static final Path HOME = Paths.get("..").toAbsolutePath().normalize();
    private static final Path ROS2 = HOME.resolve("clients/python-ros2");
    /** The ROS domain of these tests' DDS traffic (the launcher's scenario runs use others). */
    private static final String DOMAIN = "71";

    @Test
    void theRos2FaceAndBodyPassTheirTests(@TempDir Path tmp) throws Exception {
        String python = ros2Python();
        PytestRun run = PytestRun.of(List.of(python), ROS2, tmp).env("HABLA_TEST_ROS_DOMAIN", DOMAIN)
                .start(ROS2.resolve("tests"));
        assertThat(run.finished()).as("pytest finished within %d s:%n%s", PytestRun.LIMIT_S, run.log()).isTrue();
        assertThat(run.exitCode()).as("pytest in %s:%n%s", ROS2, run.log()).isZero();
        assertThat(run.log()).containsPattern("\\d+ passed").doesNotContain(" skipped");
    }

    /** The ROS 2 environment's python, or a failure that says how to make the environment. */
    private static String ros2Python() throws IOException, InterruptedException {
        Process p = new ProcessBuilder(HOME.resolve("clients/ros2-env.sh").toString(), "python").start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        assertThat(p.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as("the ROS 2 environment is missing: %s", err).isZero();
        return out;
    }
}
