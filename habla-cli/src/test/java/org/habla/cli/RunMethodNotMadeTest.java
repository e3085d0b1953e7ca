package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.habla.command.ExitCodes;
import org.habla.config.ConfigLoader;
import org.habla.config.TestPlugins;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A method's ports are read from its type, not from a made method: a config whose method cannot be made still
 * checks clean, and {@code habla run} stops at that method's JSON path with the constructor's reason.
 */
@Timeout(30)
class RunMethodNotMadeTest {

    private static Path config(Path dir) throws IOException {
        Path file = dir.resolve("unmakeable.json");
        Files.writeString(file, """
                {"system": "unmakeable", "status": {"port": 0},
                 "interfaces": [{"id": "robot", "driver": "robot-sim", "address": "127.0.0.1:9"}],
                 "methods": [
                  {"id": "sonar", "type": "sonar", "layer": "sensors_actuators", "inputs": {"ranges": "@robot.sonar"}},
                  {"id": "model", "type": "unmakeable", "layer": "processing", "inputs": {"in": "sonar.ranges"}}]}
                """);
        return file;
    }

    @Test
    void theConfigCheckReadsThePortsWithoutMakingTheMethod(@TempDir Path dir) throws Exception {
        Path file = config(dir);

        assertThat(new ConfigLoader(TestPlugins.registry()).load(file).methods()).hasSize(2);
    }

    @Test
    void aMethodItsTypeCannotMakeStopsTheRunAtItsJsonPath(@TempDir Path dir) throws Exception {
        Path file = config(dir);

        CommandRun run = CommandRun.of(new RunCommand(TestPlugins.registry()), file.toString());

        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.err().lines().toList()).containsExactly(
                file + ": 1 error; the daemon does not start:",
                "$.methods[1]: method 'model' of type 'unmakeable' cannot be made: the model file is missing");
    }
}
