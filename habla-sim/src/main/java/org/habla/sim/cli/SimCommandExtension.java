package org.habla.sim.cli;

import org.habla.cli.CommandExtension;

/** Adds {@code habla sim} to the {@code habla} command. */
public final class SimCommandExtension implements CommandExtension {

    @Override
    public String name() {
        return "sim";
    }

    @Override
    public Object command() {
        return new SimCommand();
    }
}
