package org.habla.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.habla.config.ConfigException;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.daemon.PlacementRefusedException;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code habla run CONFIG}: checks the config, starts the daemon and runs until SIGINT or SIGTERM,
 * which stop the actuators first, close the sockets and exit 0.
 */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = "Run the HABLA daemon with a config until interrupted.")
public final class RunCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "CONFIG", description = "The JSON config file.")
    private Path config;

    @Option(names = "--time-scale", paramLabel = "S", defaultValue = "1",
            description = "Run the engine's clock S times faster than the wall clock (watchdog, periodic work, "
                    + "action durations), to drive a simulated robot sped up by the same factor. Never for a real robot.")
    private double timeScale;
    private final PluginRegistry plugins;

    public RunCommand() {
        this(null);
    }

    /** A run with exactly these plugins instead of the ones on the class path. */
    public RunCommand(PluginRegistry plugins) {
        this.plugins = plugins;
    }

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter err = spec.commandLine().getErr();
        PluginRegistry registry = plugins != null ? plugins
                : PluginRegistry.discover(Thread.currentThread().getContextClassLoader());
        HablaConfig cfg;
        try {
            cfg = new ConfigLoader(registry).load(config);
        } catch (ConfigException e) {
            ConfigReport.errors(err, config, e.errors(), "the daemon does not start");
            return ExitCodes.USAGE_OR_CONFIG;
        }
        if (!(timeScale >= 1) || !Double.isFinite(timeScale)) {
            err.println("habla run: --time-scale must be 1 or more, was " + timeScale);
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        Daemon daemon;
        try {
            daemon = Daemon.start(cfg, registry, timeScale == 1 ? EngineClock.system() : EngineClock.scaled(timeScale));
        } catch (PlacementRefusedException e) {
            e.refusals().forEach(r -> err.println("habla run: " + r));
            err.println("habla run: the daemon does not start");
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        } catch (IOException e) {
            err.println("habla run: " + e.getMessage());
            err.flush();
            return ExitCodes.RUNTIME_FAILURE;
        }
        CountDownLatch stopped = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            daemon.close();
            stopped.countDown();
            // A signal is the normal way to stop a daemon: exit 0, not the JVM's 128+signal.
            Runtime.getRuntime().halt(ExitCodes.OK);
        }, "habla-shutdown"));
        stopped.await();
        return ExitCodes.OK;
    }
}
