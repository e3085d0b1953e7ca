package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.habla.command.ExitCodes;
import org.habla.config.TestPlugins;
import org.habla.testing.TestConfigs;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class GraphCommandTest {

    @TempDir
    Path dir;

    private static String config(String name) throws Exception {
        return TestConfigs.file(name).toString();
    }

    @Test
    void dotIsPrintedByDefault() throws Exception {
        CommandRun run = CommandRun.of(new GraphCommand(TestPlugins.registry()), config("valid/pioneer-like.json"));

        assertThat(run.exitCode()).isEqualTo(ExitCodes.OK);
        assertThat(run.out()).startsWith("digraph habla {").contains("\"method:nearest\"");
    }

    @Test
    void theFormatFollowsTheOutputFileExtension() throws Exception {
        Path svg = dir.resolve("figures/pioneer.svg");
        Path mermaid = dir.resolve("pioneer.mmd");

        CommandRun a = CommandRun.of(new GraphCommand(TestPlugins.registry()), config("valid/pioneer-like.json"),
                "--output", svg.toString());
        CommandRun b = CommandRun.of(new GraphCommand(TestPlugins.registry()), config("valid/pioneer-like.json"),
                "-o", mermaid.toString());

        assertThat(a.exitCode()).isEqualTo(ExitCodes.OK);
        assertThat(b.exitCode()).isEqualTo(ExitCodes.OK);
        assertThat(Files.readString(svg)).startsWith("<?xml").contains("<svg ");
        assertThat(Files.readString(mermaid)).startsWith("flowchart BT");
    }

    @Test
    void anExplicitFormatWinsAndAnUnknownOneIsAUsageError() throws Exception {
        CommandRun mermaid = CommandRun.of(new GraphCommand(TestPlugins.registry()), config("valid/pioneer-like.json"),
                "--format", "mermaid");
        CommandRun bad = CommandRun.of(new GraphCommand(TestPlugins.registry()), config("valid/pioneer-like.json"),
                "--format", "png");

        assertThat(mermaid.out()).startsWith("flowchart BT");
        assertThat(bad.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(bad.err()).contains("unknown format 'png'");
    }

    @Test
    void aBrokenConfigIsRefusedWithItsErrors() throws Exception {
        String broken = config("broken/unknown-method-reference.json");

        CommandRun run = CommandRun.of(new GraphCommand(TestPlugins.registry()), broken);

        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.out()).isEmpty();
        assertThat(run.err()).contains(broken + ": 1 error; nothing is drawn:")
                .contains("$.methods[1].inputs.ranges: unknown method 'sonr'");
    }

    @Test
    void graphIsASubcommandOfHabla() {
        assertThat(Habla.commandLine().getSubcommands()).containsKey("graph");
    }
}
