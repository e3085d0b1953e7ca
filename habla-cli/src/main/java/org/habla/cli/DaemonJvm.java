package org.habla.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

/**
 * The JVM options a daemon process runs with ({@code habla run}, {@code habla worker}): the environment's
 * {@code HABLA_JAVA_OPTS} when set, else the options in {@code config/daemon.jvm-options} of the HABLA home,
 * the file the launcher reads too. The file chooses a collector for a process that sits next to a robot for
 * days: a bounded heap that gives memory back, so neither a burst of garbage (a thousand hostile connections)
 * nor the speech model's loading leaves the resident memory grown (docs/deployment.md, "The daemon's JVM").
 */
public final class DaemonJvm {

    /** The file, relative to the HABLA home, that holds the daemon's JVM options (one line, spaces between). */
    public static final String OPTIONS_FILE = "config/daemon.jvm-options";

    private DaemonJvm() {
    }

    /** The options for a child JVM that runs {@code command}; none for commands that are not daemons. */
    public static List<String> options(Path home, String command) throws IOException {
        if (!command.equals("run") && !command.equals("worker")) {
            return List.of();
        }
        String env = System.getenv("HABLA_JAVA_OPTS");
        if (env != null) {
            return split(env);
        }
        Path file = home.resolve(OPTIONS_FILE);
        return Files.isRegularFile(file) ? split(Files.readString(file, StandardCharsets.UTF_8)) : List.of();
    }

    static List<String> split(String options) {
        return Arrays.stream(options.trim().split("\\s+")).filter(s -> !s.isEmpty()).toList();
    }
}
