package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.habla.command.ExitCodes;
import org.habla.config.ConfigSchema;
import org.habla.config.TestPlugins;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SchemaCommandTest {

    @TempDir
    Path dir;

    @Test
    void schemaIsPrintedForEveryRegisteredType() throws IOException {
        CommandRun run = CommandRun.of(new SchemaCommand(TestPlugins.registry()));

        assertThat(run.exitCode()).isEqualTo(ExitCodes.OK);
        JsonNode schema = new ObjectMapper().readTree(run.out());
        assertThat(schema.path("$defs").has("params.method.sonar")).isTrue();
        assertThat(schema.path("$defs").has("params.driver.robot-sim")).isTrue();
        assertThat(run.out()).isEqualTo(ConfigSchema.text(TestPlugins.registry()));
    }

    @Test
    void outputWritesTheSameTextToAFileInANewFolder() throws IOException {
        Path file = dir.resolve("config/habla-config.schema.json");

        CommandRun run = CommandRun.of(new SchemaCommand(TestPlugins.registry()), "--output", file.toString());

        assertThat(run.exitCode()).isEqualTo(ExitCodes.OK);
        assertThat(run.out()).startsWith("wrote " + file);
        assertThat(Files.readString(file)).isEqualTo(ConfigSchema.text(TestPlugins.registry()));
    }

    @Test
    void anUnwritableOutputIsARuntimeFailure() throws IOException {
        Path blocker = Files.writeString(dir.resolve("a-file"), "x");

        CommandRun run = CommandRun.of(new SchemaCommand(TestPlugins.registry()), "--output",
                blocker.resolve("schema.json").toString());

        assertThat(run.exitCode()).isEqualTo(ExitCodes.RUNTIME_FAILURE);
        assertThat(run.err()).startsWith("habla schema: cannot write");
    }

    @Test
    void schemaIsASubcommandOfHabla() {
        assertThat(Habla.commandLine().getSubcommands()).containsKey("schema");
    }
}
