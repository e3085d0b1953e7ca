package org.habla.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.habla.command.CommandExtension;
import org.habla.command.ExitCodes;
import org.habla.config.ConfigException;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.daemon.PlacementRefusedException;
import org.habla.daemon.PortsUnavailableException;
import org.habla.graph.EngineClock;
import org.habla.graph.MethodGraph;
import org.habla.graph.MethodNotMadeException;
import org.habla.monitor.Monitor;
import org.habla.recording.Recorder;
import org.habla.recording.RecordingHeader;
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

    @Option(names = "--record", paramLabel = "FILE",
            description = "Record every reading, command, control write and exposed output, and the config, to FILE "
                    + "(a new file; see docs/recording.md). Replay it with 'habla replay FILE'.")
    private Path record;
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
        registry.report().logTo(org.slf4j.LoggerFactory.getLogger(RunCommand.class));
        HablaConfig cfg;
        try {
            cfg = new ConfigLoader(registry).load(config);
        } catch (ConfigException e) {
            ConfigReport.errors(err, config, e.errors(), "the daemon does not start");
            return ExitCodes.USAGE_OR_CONFIG;
        }
        if (cfg.status().monitorPort() > 0) {
            // The monitor's web server is the slowest to make of the ports: its classes load meanwhile.
            Preload.inBackground("monitor", Monitor::preload);
        }
        if (!(timeScale >= 1) || !Double.isFinite(timeScale)) {
            err.println("habla run: --time-scale must be 1 or more, was " + timeScale);
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        EngineClock clock = timeScale == 1 ? EngineClock.system() : EngineClock.scaled(timeScale);
        Recorder recorder = null;
        Daemon daemon;
        try {
            Daemon.checkPorts(cfg);
            if (record != null) {
                recorder = Recorder.create(record, header(cfg, registry, clock), clock);
            }
            daemon = recorder == null ? Daemon.start(cfg, registry, clock) : Daemon.start(cfg, registry, clock, recorder);
        } catch (PortsUnavailableException e) {
            if (recorder != null) {
                recorder.close();
            }
            ConfigReport.errors(err, config, e.errors(), "the daemon does not start");
            return ExitCodes.USAGE_OR_CONFIG;
        } catch (MethodNotMadeException e) {
            if (recorder != null) {
                recorder.close();
            }
            ConfigReport.errors(err, config, java.util.List.of(e.error()), "the daemon does not start");
            return ExitCodes.USAGE_OR_CONFIG;
        } catch (PlacementRefusedException e) {
            e.refusals().forEach(r -> err.println("habla run: " + r));
            err.println("habla run: the daemon does not start");
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        } catch (FileAlreadyExistsException e) {
            err.println("habla run: " + record + " already exists; a recording is never overwritten");
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        } catch (IOException e) {
            if (recorder != null) {
                recorder.close();
            }
            err.println("habla run: " + e.getMessage());
            err.flush();
            return ExitCodes.RUNTIME_FAILURE;
        }
        Recorder rec = recorder;
        CountDownLatch stopped = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            daemon.close();
            if (rec != null) {
                rec.close();
            }
            stopped.countDown();
            // A signal is the normal way to stop a daemon: exit 0, not the JVM's 128+signal.
            Runtime.getRuntime().halt(ExitCodes.OK);
        }, "habla-shutdown"));
        stopped.await();
        return ExitCodes.OK;
    }

    private RecordingHeader header(HablaConfig cfg, PluginRegistry registry, EngineClock clock) throws IOException {
        ObjectNode json = (ObjectNode) new ObjectMapper().readTree(Files.readString(config));
        Path dir = config.toAbsolutePath().getParent();
        return new RecordingHeader(clock.nowMicros(), timeScale, json, dir == null ? "" : dir.toString(),
                MethodGraph.channels(cfg, registry));
    }

    /**
     * Adds {@code habla run} to the command line. RunCommand's class is loaded only when it is named: it needs the
     * recording, which a worker's class path does not have.
     */
    public static final class Extension implements CommandExtension {

        @Override
        public String name() {
            return "run";
        }

        @Override
        public Object command() {
            return new RunCommand();
        }
    }
}
