package org.habla.sim.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code habla sim ROBOT}: runs a simulated robot behind its real protocol's sockets, with its world and teacher. */
@Command(name = "sim", mixinStandardHelpOptions = true,
        description = "Run a simulated robot in its world, behind the same sockets as the real robot.",
        subcommands = {SimPioneerCommand.class, SimAiboCommand.class})
public final class SimCommand implements Runnable {

    @Spec
    private CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }
}
