package org.habla.cli;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.Logger;
import java.io.File;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.function.Supplier;
import org.habla.command.CommandExtension;
import org.habla.command.ExitCodes;
import org.habla.config.ConfigLoader;
import org.habla.plugin.PluginJars;
import org.slf4j.LoggerFactory;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The {@code habla} command: the daemon and its tools. The commands that run a daemon ({@code run}, {@code replay})
 * and the subcommands of other modules (the simulator, the scenarios) join through {@link CommandExtension}, so the
 * command line of a worker, whose class path has neither the monitor nor the recording, never loads them.
 */
@Command(name = "habla", mixinStandardHelpOptions = true, versionProvider = Habla.Version.class,
        description = "HABLA, the Hardware Abstraction Layer: isolates a robot's control architecture from its hardware.")
public final class Habla implements Runnable {

    /**
     * The built-in subcommands. They are made when a command line is, and only the one named when a known one is:
     * picocli reads every command's annotations as it adds it, which was a fifth of a daemon's time to its first
     * open port.
     */
    private static final Map<String, Supplier<Object>> BUILT_IN = builtIn();
    /** The order help lists these commands in, wherever they come from; the other modules' commands follow. */
    private static final List<String> HELP_ORDER =
            List.of("run", "replay", "check", "graph", "schema", "plugins", "status", "worker");

    private static Map<String, Supplier<Object>> builtIn() {
        Map<String, Supplier<Object>> m = new LinkedHashMap<>();
        m.put("check", CheckCommand::new);
        m.put("graph", GraphCommand::new);
        m.put("schema", SchemaCommand::new);
        m.put("plugins", PluginsCommand::new);
        m.put("status", StatusCommand::new);
        m.put("worker", org.habla.worker.WorkerCommand::new);
        return java.util.Collections.unmodifiableMap(m);
    }

    @Option(names = "--log-level", scope = CommandLine.ScopeType.INHERIT, paramLabel = "LEVEL",
            description = "error, warn, info (default), debug or trace.")
    void logLevel(String level) {
        Level l = Level.toLevel(level, null);
        if (l == null) {
            throw new CommandLine.ParameterException(new CommandLine(this), "unknown log level '" + level + "'");
        }
        ((Logger) LoggerFactory.getLogger(org.slf4j.Logger.ROOT_LOGGER_NAME)).setLevel(l);
    }

    @Option(names = "--plugins", scope = CommandLine.ScopeType.INHERIT, paramLabel = "DIR",
            description = "A folder of plugin jars (method, driver and bridge types), or one jar, to load; default ./plugins if present.")
    File plugins;

    @Override
    public void run() {
        CommandLine.usage(this, System.out);
    }

    public static void main(String[] args) {
        System.exit(execute(args));
    }

    /** Runs the command line and returns the exit code. */
    public static int execute(String... args) {
        if ("run".equals(subcommand(args))) {
            // Jackson's readers take about as long to make as picocli the command line: both at once.
            Preload.inBackground("config", ConfigLoader::preload);
        }
        ClassLoader loader = pluginLoader(args);
        Thread.currentThread().setContextClassLoader(loader);
        CommandLine cli = commandLine(loader, subcommand(args));
        cli.setExecutionExceptionHandler((e, cmd, parsed) -> {
            cmd.getErr().println("habla: " + e);
            LoggerFactory.getLogger(Habla.class).error("command failed", e);
            return ExitCodes.RUNTIME_FAILURE;
        });
        cli.setExitCodeExceptionMapper(e -> ExitCodes.RUNTIME_FAILURE);
        cli.getCommandSpec().exitCodeOnInvalidInput(ExitCodes.USAGE_OR_CONFIG);
        return cli.execute(args);
    }

    /** The whole command line: every built-in subcommand and every one other modules add. */
    public static CommandLine commandLine() {
        return commandLine(Habla.class.getClassLoader(), null);
    }

    /** The command line with only subcommand {@code only} when it is a known one, else with all of them. */
    private static CommandLine commandLine(ClassLoader loader, String only) {
        Map<String, Supplier<Object>> commands = new LinkedHashMap<>();
        HELP_ORDER.forEach(name -> commands.put(name, null));
        commands.putAll(BUILT_IN);
        for (CommandExtension ext : ServiceLoader.load(CommandExtension.class, loader)) {
            if (commands.put(ext.name(), ext::command) != null) {
                throw new IllegalStateException("two commands are named '" + ext.name() + "'");
            }
        }
        boolean known = only != null && commands.get(only) != null;
        CommandLine cli = new CommandLine(new Habla());
        commands.forEach((name, command) -> {
            if (command != null && (!known || name.equals(only))) {
                cli.addSubcommand(name, command.get());
            }
        });
        return cli;
    }

    /** The first argument that is neither an option of {@code habla} itself nor its value, or null. */
    static String subcommand(String[] args) {
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals("--plugins") || args[i].equals("--log-level")) {
                i++;
            } else if (!args[i].startsWith("-")) {
                return args[i];
            }
        }
        return null;
    }

    /** A class loader over the plugin jars named by --plugins (a folder or one jar), else in ./plugins. */
    private static ClassLoader pluginLoader(String[] args) {
        Path named = null;
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals("--plugins") && i + 1 < args.length) {
                named = Path.of(args[i + 1]);
            } else if (args[i].startsWith("--plugins=")) {
                named = Path.of(args[i].substring("--plugins=".length()));
            }
        }
        return PluginJars.open(named, Habla.class.getClassLoader()).loader();
    }

    /** The version from the jar's manifest, or "development". */
    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = Habla.class.getPackage().getImplementationVersion();
            return new String[] {"HABLA " + (v == null ? "0.1.0-SNAPSHOT (development build)" : v),
                    "Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vendor") + ")"};
        }
    }
}
