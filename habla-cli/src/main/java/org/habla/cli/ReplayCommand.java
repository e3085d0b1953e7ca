package org.habla.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.habla.command.CommandExtension;
import org.habla.command.ExitCodes;
import org.habla.config.ConfigException;
import org.habla.daemon.PortsUnavailableException;
import org.habla.plugin.PluginRegistry;
import org.habla.recording.RecordingDamagedException;
import org.habla.recording.RecordingException;
import org.habla.replay.ReplayResult;
import org.habla.replay.Replayer;
import org.habla.replay.StreamMatch;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code habla replay FILE}: runs the daemon of a recording with the recorded readings in place of the robot,
 * the same control sockets open, and says how the exposed outputs compare with the recorded ones.
 */
@Command(name = "replay", mixinStandardHelpOptions = true,
        description = "Run the daemon on a recording made with 'habla run --record' instead of a robot, and compare "
                + "its exposed outputs and commands with the recorded ones.")
public final class ReplayCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE", description = "The recording.")
    private Path file;

    @ArgGroup(exclusive = true)
    private Pace pace = new Pace();

    static final class Pace {
        @Option(names = "--speed", paramLabel = "S", defaultValue = "1",
                description = "Replay S times faster than recorded (default 1: the recorded pace).")
        double speed = 1;

        @Option(names = "--as-fast-as-possible", description = "Replay without waiting between events.")
        boolean fast;
    }

    @Option(names = "--config", paramLabel = "OVERRIDE",
            description = "Replay with this config instead of the recorded one (same interfaces and channels).")
    private Path override;

    @Option(names = "--record", paramLabel = "OUT", description = "Record the replay to a new file OUT.")
    private Path recordTo;

    @Option(names = "--no-control", description = "Do not replay the recorded control writes; only live clients write.")
    private boolean noControl;

    @Option(names = "--salvage", description = "Replay a recording damaged before its end up to the damage "
            + "(without it such a recording is refused, naming the byte offset).")
    private boolean salvage;

    @Option(names = "--strict", description = "Exit 1 if any exposed output or command differs from the recording.")
    private boolean strict;

    private final PluginRegistry plugins;

    public ReplayCommand() {
        this(null);
    }

    /** A replay with exactly these plugins instead of the ones on the class path. */
    public ReplayCommand(PluginRegistry plugins) {
        this.plugins = plugins;
    }

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        PluginRegistry registry = plugins != null ? plugins
                : PluginRegistry.discover(Thread.currentThread().getContextClassLoader());
        if (!pace.fast && !(pace.speed > 0 && Double.isFinite(pace.speed))) {
            return fail(err, "--speed must be above 0, was " + pace.speed, ExitCodes.USAGE_OR_CONFIG);
        }
        Replayer replayer;
        try {
            replayer = Replayer.open(file, Optional.ofNullable(override), registry, salvage);
        } catch (RecordingDamagedException e) {
            return fail(err, file + ": " + e.getMessage() + ". Nothing was replayed; --salvage replays the part"
                    + " before byte " + e.cut().offset(), ExitCodes.USAGE_OR_CONFIG);
        } catch (ConfigException e) {
            ConfigReport.errors(err, override != null ? override : file, e.errors(), "the replay does not start");
            return ExitCodes.USAGE_OR_CONFIG;
        } catch (RecordingException e) {
            return fail(err, file + ": " + e.getMessage(), ExitCodes.USAGE_OR_CONFIG);
        } catch (IOException e) {
            return fail(err, "cannot read " + file + ": " + e, ExitCodes.USAGE_OR_CONFIG);
        }
        Replayer.Options options = new Replayer.Options(pace.fast ? 0 : pace.speed, !noControl, 10_000);
        ReplayResult r;
        try {
            r = replayer.run(options, Optional.ofNullable(recordTo), d -> {
                out.println("replaying " + file + " (" + replayer.config().system() + ")"
                        + (pace.fast ? " as fast as possible" : " at speed " + pace.speed));
                out.flush();
            });
        } catch (FileAlreadyExistsException e) {
            return fail(err, recordTo + " already exists; a recording is never overwritten", ExitCodes.USAGE_OR_CONFIG);
        } catch (PortsUnavailableException e) {
            ConfigReport.errors(err, override != null ? override : file, e.errors(), "the replay does not start");
            return ExitCodes.USAGE_OR_CONFIG;
        } catch (IOException | RecordingException e) {
            return fail(err, e.getMessage(), ExitCodes.RUNTIME_FAILURE);
        }
        out.printf("replayed %d readings, %d control writes (%d refused), %d ticks: %.1f s recorded in %.1f s%n",
                r.readings(), r.controlWrites(), r.rejected(), r.ticks(), r.recordedMicros() / 1e6, r.wallMillis() / 1e3);
        boolean allMatch = true;
        for (StreamMatch s : r.streams()) {
            out.println("  " + s);
            allMatch &= s.matches();
        }
        if (r.cut().isPresent()) {
            out.println(r.cut().get().describe() + ": everything before it was replayed");
        } else if (!r.complete()) {
            out.println("the recording has no end record: the recording daemon did not stop cleanly");
        }
        if (r.recordedDrops() > 0) {
            out.println("the recorder had dropped " + r.recordedDrops() + " events: outputs may differ where they were");
        }
        if (r.unsettled() > 0) {
            out.println(r.unsettled() + " events did not settle within " + options.settleMillis() + " ms");
        }
        out.flush();
        return strict && !allMatch ? ExitCodes.RUNTIME_FAILURE : ExitCodes.OK;
    }

    private static int fail(PrintWriter err, String message, int code) {
        err.println("habla replay: " + message);
        err.flush();
        return code;
    }

    /**
     * Adds {@code habla replay} to the command line. ReplayCommand's class is loaded only when it is named: it needs the
     * recording, which a worker's class path does not have.
     */
    public static final class Extension implements CommandExtension {

        @Override
        public String name() {
            return "replay";
        }

        @Override
        public Object command() {
            return new ReplayCommand();
        }
    }
}
