package org.habla.sim.cli;

import org.habla.command.CommandExtension;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code habla sim}: runs a simulated robot behind its real wire protocols on loopback. */
@Command(name = "sim", mixinStandardHelpOptions = true,
        description = "Run a simulated robot: its own servers on loopback, its world and its teacher, and a "
                + "ground-truth server. Stops on Ctrl-C or SIGTERM.",
        subcommands = {SimPioneerCommand.class, SimAiboCommand.class, SimRoomCommand.class})
public final class SimCommand implements Runnable {

    @Override
    public void run() {
        CommandLine.usage(this, System.out);
    }

    /** Registers {@code sim} with {@code habla}. */
    public static final class Extension implements CommandExtension {

        @Override
        public String name() {
            return "sim";
        }

        @Override
        public Object command() {
            return new SimCommand();
        }
    }
}
