package org.habla.sim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.habla.command.ExitCodes;
import org.habla.sim.aibo.AiboSimulator;
import org.habla.sim.aibo.TekkotsuPorts;
import org.habla.sim.world.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code habla sim aibo}: a simulated Sony Aibo ERS-7 with Tekkotsu's servers on loopback (controller
 * 10020, e-stop 10053, world state 10031, walk 10050, head 10052, microphone 10070, speaker 10071, raw
 * camera 10011, all moved by {@code --port-base}), in an arena with a pink ball and a teacher who speaks
 * commands and rewards by touch; ground truth on 10199.
 */
@Command(name = "aibo", mixinStandardHelpOptions = true,
        description = {"Run a simulated Sony Aibo ERS-7 behind Tekkotsu's servers on 127.0.0.1.",
                "Point HABLA's tekkotsu driver at 127.0.0.1 (with the ports moved by the port base, if any)."})
public final class SimAiboCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Option(names = "--world", paramLabel = "FILE",
            description = "A world file, or the name of a built-in world (default: aibo-arena).")
    private String world = "aibo-arena";

    @Option(names = "--speed", paramLabel = "S", defaultValue = "1",
            description = "Time scale: the robot and its world run S times faster than real time (S >= 1; default 1).")
    private double speed;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1",
            description = "Seed of the sensor noise and the teacher's choice of takes (default 1).")
    private long seed;

    @Option(names = "--port-base", paramLabel = "B", defaultValue = "10000",
            description = "Tekkotsu's ports are 10000 + n; with B they are B + n (default 10000).")
    private int portBase;

    @Option(names = "--truth-port", paramLabel = "P", defaultValue = "10199",
            description = "Port of the ground-truth server (default 10199; 0 = any free port).")
    private int truthPort;

    @Option(names = "--teacher", paramLabel = "on|off", defaultValue = "on",
            description = "Whether the teacher is there at the start (default on).")
    private String teacher;

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter out = spec.commandLine().getOut();
        String problem = check();
        World w = null;
        if (problem == null) {
            try {
                w = loadWorld(world);
            } catch (IOException | RuntimeException e) {
                problem = "cannot read the world '" + world + "': " + e.getMessage();
            }
        }
        if (problem != null) {
            err.println("habla sim aibo: " + problem);
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        AiboSimulator sim;
        try {
            sim = new AiboSimulator(AiboSimulator.Options.defaults(w).withSpeed(speed).withSeed(seed)
                    .withPorts(TekkotsuPorts.withBase(portBase), truthPort).withTeacher(teacher.equals("on")));
        } catch (IOException e) {
            err.println("habla sim aibo: cannot listen: " + e.getMessage()
                    + " (another robot or simulator on these ports? try --port-base)");
            err.flush();
            return ExitCodes.RUNTIME_FAILURE;
        }
        CountDownLatch stopped = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            sim.close();
            stopped.countDown();
        }, "sim-aibo-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        sim.start();
        TekkotsuPorts p = sim.ports();
        out.printf("simulated Aibo in world '%s' at %sx speed: controller %d, e-stop %d, world state %d, walk %d, "
                + "head %d, microphone %d, speaker %d, raw camera %d; ground truth %d%n", w.name(), speed,
                p.controller(), p.eStop(), p.worldState(), p.walk(), p.head(), p.microphone(), p.speaker(),
                p.rawCam(), sim.truthPort());
        out.flush();
        stopped.await();
        return ExitCodes.OK;
    }

    private String check() {
        if (!(speed >= 1) || Double.isInfinite(speed)) {
            return "--speed must be a number >= 1, was " + speed;
        }
        if (!teacher.equals("on") && !teacher.equals("off")) {
            return "--teacher takes on or off, not '" + teacher + "'";
        }
        if (truthPort < 0 || truthPort > 65_535) {
            return "--truth-port must be in 0..65535, was " + truthPort;
        }
        try {
            TekkotsuPorts.withBase(portBase);
        } catch (IllegalArgumentException e) {
            return "--port-base: " + e.getMessage();
        }
        return null;
    }

    /** A file if one exists at that path, else a built-in world by name (with or without {@code .json}). */
    static World loadWorld(String name) throws IOException {
        return World.named(name);
    }
}
