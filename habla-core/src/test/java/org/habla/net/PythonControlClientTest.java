package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Runs the unit tests of the example Python control client ({@code examples/control-python}) with
 * {@code python3 -m unittest}, so the client that documents the control protocol stays correct.
 */
@Timeout(120)
class PythonControlClientTest {

    private static final Path CLIENT = Paths.get("..", "examples", "control-python").toAbsolutePath().normalize();

    @Test
    void pythonClientUnitTestsPass() throws Exception {
        ProcessBuilder pb = new ProcessBuilder("python3", "-m", "unittest", "-v", "test_habla_client")
                .directory(CLIENT.toFile()).redirectErrorStream(true);
        pb.environment().put("PYTHONDONTWRITEBYTECODE", "1");
        Process p = pb.start();
        p.getOutputStream().close();
        byte[] output;
        try (var in = p.getInputStream()) {
            output = in.readAllBytes();
        }
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).as("python3 -m unittest finished").isTrue();
        String text = new String(output, StandardCharsets.UTF_8);
        assertThat(p.exitValue()).as("python3 -m unittest test_habla_client:\n" + text).isZero();
        assertThat(text).containsPattern("test_json_that_is_not_an_object_is_reported_and_reading_goes_on\\b.*\\.\\.\\. ok")
                .containsPattern("Ran \\d+ tests");
    }
}
