package org.habla.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine.Model.CommandSpec;

/** Where a command that produces one text puts it: standard output, or a file (its folders made first). */
final class CommandOutput {

    private CommandOutput() {
    }

    /**
     * Prints {@code text}, or writes it to {@code file} when one is given; a file that cannot be written is said on
     * the command's error stream as "habla COMMAND: cannot write FILE: why".
     *
     * @return whether the text went out
     */
    static boolean put(CommandSpec spec, Path file, String text) {
        if (file == null) {
            PrintWriter out = spec.commandLine().getOut();
            out.print(text);
            out.flush();
            return true;
        }
        try {
            Path parent = file.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            Files.writeString(file, text, StandardCharsets.UTF_8);
            return true;
        } catch (IOException e) {
            PrintWriter err = spec.commandLine().getErr();
            err.println("habla " + spec.name() + ": cannot write " + file + ": " + e);
            err.flush();
            return false;
        }
    }
}
