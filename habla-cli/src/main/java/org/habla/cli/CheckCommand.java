package org.habla.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.habla.command.ExitCodes;
import org.habla.config.ConfigException;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.plugin.PluginRegistry;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code habla check CONFIG}: reads a config exactly as {@code habla run} would, without starting
 * anything. A bad config gets every error with its JSON path and exit code 2; a valid one gets a
 * summary of what would run and exit code 0.
 */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = "Check a config: list every error with its JSON path, or summarise what it would run.")
public final class CheckCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "CONFIG", description = "The JSON config file.")
    private Path config;

    private final PluginRegistry registry;

    public CheckCommand() {
        this(null);
    }

    /** A check against exactly these plugins instead of the ones on the class path. */
    public CheckCommand(PluginRegistry registry) {
        this.registry = registry;
    }

    @Override
    public Integer call() {
        PluginRegistry r = registry != null ? registry : PluginRegistry.discover(Thread.currentThread().getContextClassLoader());
        HablaConfig cfg;
        PrintWriter err = spec.commandLine().getErr();
        try {
            cfg = new ConfigLoader(r).load(config);
        } catch (ConfigException e) {
            ConfigReport.errors(err, config, e.errors(), "");
            if (e.errors().stream().noneMatch(x -> x.message().contains("plugins: "))) {
                ConfigReport.pluginProblems(err, r.report());
            }
            return ExitCodes.USAGE_OR_CONFIG;
        }
        PrintWriter out = spec.commandLine().getOut();
        out.println(ConfigReport.summary(config, cfg));
        r.report().loaded().forEach(line -> out.println("plugin " + line));
        out.flush();
        ConfigReport.pluginProblems(err, r.report());
        return ExitCodes.OK;
    }
}
