package org.habla.cli;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.habla.command.ExitCodes;
import picocli.CommandLine;

/** One in-process run of a picocli command with its output and error streams captured. */
record CommandRun(int exitCode, String out, String err) {

    static CommandRun of(Object command, String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = new CommandLine(command);
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        cli.getCommandSpec().exitCodeOnInvalidInput(ExitCodes.USAGE_OR_CONFIG);
        int code = cli.execute(args);
        return new CommandRun(code, out.toString(), err.toString());
    }

    /** The output with line breaks turned into spaces, for phrases a wrapped paragraph may split. */
    String outFlat() {
        return out.strip().replaceAll("\\s*\\R\\s*", " ");
    }
}
