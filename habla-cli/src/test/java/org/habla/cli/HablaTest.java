package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import org.habla.command.ExitCodes;
import org.junit.jupiter.api.Test;

class HablaTest {

    @Test
    void theWholeCommandLineListsTheDaemonsCommandsFirstThenTheBuiltInOnes() {
        assertThat(Habla.commandLine().getSubcommands().keySet())
                .startsWith("run", "replay", "check", "graph", "schema", "plugins", "status", "worker");
    }

    @Test
    void theSubcommandIsTheFirstArgumentThatIsNotAnOptionOfHablaOrItsValue() {
        assertThat(Habla.subcommand(new String[] {"--log-level", "debug", "--plugins", "run", "check", "x.json"}))
                .isEqualTo("check");
        assertThat(Habla.subcommand(new String[] {"--log-level=debug", "run", "x.json"})).isEqualTo("run");
        assertThat(Habla.subcommand(new String[] {"--version"})).isNull();
    }

    @Test
    void anUnknownSubcommandFailsWithEverySubcommandToSuggest() {
        java.io.PrintStream err = System.err;
        var captured = new java.io.ByteArrayOutputStream();
        System.setErr(new java.io.PrintStream(captured, true, java.nio.charset.StandardCharsets.UTF_8));
        try {
            assertThat(Habla.execute("chek")).isEqualTo(ExitCodes.RUNTIME_FAILURE);
        } finally {
            System.setErr(err);
        }
        assertThat(captured.toString(java.nio.charset.StandardCharsets.UTF_8)).contains("habla check");
    }

    @Test
    void aKnownSubcommandStillRunsWithHablasOwnOptionsBeforeIt() {
        assertThat(Habla.execute("--log-level", "warn", "schema", "--help")).isEqualTo(ExitCodes.OK);
    }
}
