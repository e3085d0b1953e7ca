package org.habla.sim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.habla.command.ExitCodes;
import org.habla.sim.pioneer.PioneerSim;
import org.habla.sim.pioneer.PioneerSimOptions;
import org.habla.sim.world.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code habla sim pioneer}: a simulated Pioneer 2 DX on 127.0.0.1 — ARCOS on 8101, the laptop microphone on 8110,
 * the teacher's keyboard on 8111, ground truth on 8199 — until interrupted (or for {@code --duration} sim seconds).
 */
@Command(name = "pioneer", mixinStandardHelpOptions = true,
        description = {"Run a simulated Pioneer 2 DX (ARCOS), its microphone, the teacher's keyboard and the "
                + "ground-truth server on 127.0.0.1.",
                "A daemon config for the real robot works unchanged against it."})
public final class SimPioneerCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Option(names = "--world", paramLabel = "FILE",
            description = "A world file, or the name of a built-in world (default: pioneer-room).")
    private String world;

    @Option(names = "--speed", paramLabel = "S", defaultValue = "1",
            description = "Sim time runs S times faster than real time, S >= 1 (default ${DEFAULT-VALUE}).")
    private double speed;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1",
            description = "Seed of the sensor noise (default ${DEFAULT-VALUE}).")
    private long seed;

    @Option(names = "--port", paramLabel = "P", defaultValue = "" + PioneerSimOptions.DEFAULT_ARCOS_PORT,
            description = "ARCOS port (default ${DEFAULT-VALUE}; 0 picks a free one).")
    private int port;

    @Option(names = "--mic-port", paramLabel = "P", defaultValue = "" + PioneerSimOptions.DEFAULT_MIC_PORT,
            description = "Microphone PCM stream port, 16 kHz s16le mono (default ${DEFAULT-VALUE}).")
    private int micPort;

    @Option(names = "--keys-port", paramLabel = "P", defaultValue = "" + PioneerSimOptions.DEFAULT_KEYS_PORT,
            description = "The teacher's keyboard line port (default ${DEFAULT-VALUE}).")
    private int keysPort;

    @Option(names = "--truth-port", paramLabel = "P", defaultValue = "" + PioneerSimOptions.DEFAULT_TRUTH_PORT,
            description = "Ground-truth server port (default ${DEFAULT-VALUE}).")
    private int truthPort;

    @Option(names = "--teacher", paramLabel = "on|off", defaultValue = "on",
            description = "Whether the teacher starts present (default ${DEFAULT-VALUE}).")
    private String teacher;

    @Option(names = "--sonar-noise", paramLabel = "M", defaultValue = "" + PioneerSimOptions.DEFAULT_SONAR_NOISE_M,
            description = "Standard deviation of the sonar noise in metres (default ${DEFAULT-VALUE}).")
    private double sonarNoiseM;

    @Option(names = "--duration", paramLabel = "S", defaultValue = "0",
            description = "Stop after S seconds of sim time (default 0: run until interrupted).")
    private double durationS;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        PioneerSimOptions options;
        try {
            if (!teacher.equals("on") && !teacher.equals("off")) {
                throw new IllegalArgumentException("--teacher must be on or off, not '" + teacher + "'");
            }
            if (!(durationS >= 0)) {
                throw new IllegalArgumentException("--duration must be >= 0");
            }
            World w = world == null ? World.builtIn("pioneer-room") : World.named(world);
            options = new PioneerSimOptions(w, speed, seed, port, micPort, keysPort, truthPort, teacher.equals("on"),
                    sonarNoiseM);
        } catch (IOException | IllegalArgumentException e) {
            err.println("habla sim pioneer: " + e.getMessage());
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        PioneerSim sim;
        try {
            sim = PioneerSim.start(options);
        } catch (IOException e) {
            err.println("habla sim pioneer: " + e.getMessage());
            err.flush();
            return ExitCodes.RUNTIME_FAILURE;
        }
        out.printf("simulated Pioneer in '%s' at %sx%n", options.world().name(), speed);
        out.printf("arcos 127.0.0.1:%d%nmicrophone 127.0.0.1:%d%nkeyboard 127.0.0.1:%d%nground-truth 127.0.0.1:%d%n",
                sim.arcosPort(), sim.micPort(), sim.keysPort(), sim.truthPort());
        out.flush();
        if (durationS > 0) {
            while (!sim.clock().awaitSimTime(durationS, 1_000)) {
                // keep waiting; sim time always advances
            }
            sim.close();
            return ExitCodes.OK;
        }
        CountDownLatch stopped = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            sim.close();
            stopped.countDown();
            // A signal is the normal way to stop a simulator: exit 0, not the JVM's 128+signal.
            Runtime.getRuntime().halt(ExitCodes.OK);
        }, "habla-sim-shutdown"));
        stopped.await();
        return ExitCodes.OK;
    }
}
