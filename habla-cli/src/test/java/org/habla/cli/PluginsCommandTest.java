package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import org.habla.command.ExitCodes;
import org.habla.config.TestPlugins;
import org.junit.jupiter.api.Test;

/** {@code habla plugins} lists each method type's ports as its type lists them, without making a method. */
class PluginsCommandTest {

    @Test
    void everyMethodTypeShowsItsPortsForTheDefaultParams() {
        CommandRun run = CommandRun.of(new PluginsCommand(TestPlugins.registry()));

        assertThat(run.exitCode()).isEqualTo(ExitCodes.OK);
        assertThat(run.out()).contains("""
                  safety  [processing]  test type safety
                      label: String = "step"  Label of the step
                      verbose: boolean = false  Whether to log each step
                      input velocity (vector, latest)
                      optional input nearest (number, latest)
                      output velocity (vector)
                """);
    }

    @Test
    void eachParameterShowsItsDeclaredRange() {
        CommandRun run = CommandRun.of(new PluginsCommand(TestPlugins.registry()));

        assertThat(run.out()).contains("""
                      maxRangeM: double [m] = 5.0, greater than 0  Ranges beyond this are reported as this
                      minRangeM: double [m] = 0.1, at least 0  Ranges below this are ignored
                      use: List<Integer> = [], within [0, 31]  Which transducers to use; empty means all
                """);
    }

    @Test
    void aTypeWhosePortsCannotBeListedForTheDefaultsSaysSoAndIsNeverMade() {
        CommandRun run = CommandRun.of(new PluginsCommand(TestPlugins.registry()));

        assertThat(run.out()).contains("""
                  broken-model  [processing]  test type broken-model
                      ports: as its parameters say (the defaults alone do not make a method of it)
                """);
    }
}
