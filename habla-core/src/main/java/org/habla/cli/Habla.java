package org.habla.cli;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.Logger;
import java.io.File;
import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.ServiceLoader;
import java.util.stream.Stream;
import org.slf4j.LoggerFactory;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The {@code habla} command: the daemon and its tools. Subcommands from other modules (the
 * simulator, the scenarios, the worker) join through {@link CommandExtension}.
 */
@Command(name = "habla", mixinStandardHelpOptions = true, versionProvider = Habla.Version.class,
        description = "HABLA, the Hardware Abstraction Layer: isolates a robot's control architecture from its hardware.",
        subcommands = {RunCommand.class, ReplayCommand.class, CheckCommand.class, GraphCommand.class, SchemaCommand.class,
                PluginsCommand.class, StatusCommand.class, org.habla.worker.WorkerCommand.class})
public final class Habla implements Runnable {

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
            description = "A folder of plugin jars (method and driver types) to load; default ./plugins if present.")
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
        ClassLoader loader = pluginLoader(args);
        Thread.currentThread().setContextClassLoader(loader);
        CommandLine cli = new CommandLine(new Habla());
        for (CommandExtension ext : ServiceLoader.load(CommandExtension.class, loader)) {
            cli.addSubcommand(ext.name(), ext.command());
        }
        cli.setExecutionExceptionHandler((e, cmd, parsed) -> {
            cmd.getErr().println("habla: " + e);
            LoggerFactory.getLogger(Habla.class).error("command failed", e);
            return ExitCodes.RUNTIME_FAILURE;
        });
        cli.setExitCodeExceptionMapper(e -> ExitCodes.RUNTIME_FAILURE);
        cli.getCommandSpec().exitCodeOnInvalidInput(ExitCodes.USAGE_OR_CONFIG);
        return cli.execute(args);
    }

    /** A class loader over the plugin jars named by --plugins (or ./plugins), else the application's. */
    private static ClassLoader pluginLoader(String[] args) {
        Path dir = null;
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals("--plugins") && i + 1 < args.length) {
                dir = Path.of(args[i + 1]);
            } else if (args[i].startsWith("--plugins=")) {
                dir = Path.of(args[i].substring("--plugins=".length()));
            }
        }
        if (dir == null && Files.isDirectory(Path.of("plugins"))) {
            dir = Path.of("plugins");
        }
        ClassLoader parent = Habla.class.getClassLoader();
        if (dir == null || !Files.isDirectory(dir)) {
            return parent;
        }
        List<URL> jars = new ArrayList<>();
        try (Stream<Path> files = Files.list(dir)) {
            for (Path p : files.filter(f -> f.toString().endsWith(".jar")).sorted().toList()) {
                jars.add(p.toUri().toURL());
            }
        } catch (MalformedURLException e) {
            throw new IllegalStateException(e);
        } catch (IOException e) {
            System.err.println("habla: cannot read the plugins folder " + dir + ": " + e.getMessage());
        }
        return new URLClassLoader(jars.toArray(URL[]::new), parent);
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
