package org.habla.sim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.habla.command.ExitCodes;
import org.habla.driver.InterfaceAddress;
import org.habla.sim.room.MosquittoBroker;
import org.habla.sim.room.RoomSim;
import org.habla.sim.room.RoomSimOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code habla sim room}: a simulated room of three zones on an MQTT broker, its devices speaking as Zigbee2MQTT's,
 * until interrupted (or for {@code --duration} sim seconds).
 */
@Command(name = "room", mixinStandardHelpOptions = true,
        description = {"Run a simulated room on an MQTT broker: motion and light sensors, lamps, a door, a climate "
                + "sensor and the teacher's button, as Zigbee2MQTT devices (state topics, /set, availability).",
                "config/room.json works unchanged against it."})
public final class SimRoomCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Option(names = "--broker", paramLabel = "HOST:PORT", defaultValue = "127.0.0.1:1883",
            description = "The MQTT broker (default ${DEFAULT-VALUE}).")
    private String broker;

    @Option(names = "--start-broker", description = "Start a Mosquitto broker on the --broker port first "
            + "(needs the Debian package mosquitto).")
    private boolean startBroker;

    @Option(names = "--base-topic", paramLabel = "T", defaultValue = RoomSimOptions.DEFAULT_BASE_TOPIC,
            description = "The devices' base topic (default ${DEFAULT-VALUE}).")
    private String baseTopic;

    @Option(names = "--speed", paramLabel = "S", defaultValue = "1",
            description = "Sim time runs S times faster than real time, S >= 1 (default ${DEFAULT-VALUE}).")
    private double speed;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1",
            description = "Seed of the person's walk and the clouds (default ${DEFAULT-VALUE}).")
    private long seed;

    @Option(names = "--day", paramLabel = "S", defaultValue = "600",
            description = "Length of a simulated day in sim seconds (default ${DEFAULT-VALUE}).")
    private double daySeconds;

    @Option(names = "--day-phase", paramLabel = "F", defaultValue = "0.4",
            description = "Where in the day it starts: 0 sunrise, 0.25 noon, 0.5 sunset, 0.75 midnight "
                    + "(default ${DEFAULT-VALUE}).")
    private double dayPhase;

    @Option(names = "--report", paramLabel = "S", defaultValue = "1",
            description = "Motion sensors report illuminance at least this often, in sim seconds "
                    + "(default ${DEFAULT-VALUE}).")
    private double reportS;

    @Option(names = "--teacher", paramLabel = "S", defaultValue = "0",
            description = "The teacher judges lamp commands for the first S sim seconds (default ${DEFAULT-VALUE}).")
    private double teacherS;

    @Option(names = "--duration", paramLabel = "S", defaultValue = "0",
            description = "Stop after S seconds of sim time (default 0: run until interrupted).")
    private double durationS;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        RoomSimOptions options;
        try {
            InterfaceAddress a = InterfaceAddress.parse(broker);
            options = new RoomSimOptions(a.host(), a.portOr(1883), baseTopic, speed, seed, daySeconds, dayPhase,
                    reportS, teacherS);
            if (!(durationS >= 0)) {
                throw new IllegalArgumentException("--duration must be >= 0");
            }
        } catch (IllegalArgumentException e) {
            err.println("habla sim room: " + e.getMessage());
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        MosquittoBroker own = null;
        RoomSim sim;
        try {
            if (startBroker) {
                own = MosquittoBroker.start(options.brokerPort(), Files.createTempDirectory("habla-sim-room-broker"));
            }
            sim = RoomSim.start(options);
        } catch (IOException e) {
            if (own != null) {
                own.close();
            }
            err.println("habla sim room: " + e.getMessage());
            err.flush();
            return ExitCodes.RUNTIME_FAILURE;
        }
        MosquittoBroker broker = own;
        out.printf("simulated room on %s:%d at %sx, devices under %s/: %s%n", options.brokerHost(), options.brokerPort(),
                speed, baseTopic, String.join(", ", sim.devices()));
        out.printf("ground truth on %s%n", RoomSimOptions.TRUTH_TOPIC);
        out.flush();
        if (durationS > 0) {
            while (!sim.clock().awaitSimTime(durationS, 1_000)) {
                // sim time always advances
            }
            sim.close();
            if (broker != null) {
                broker.close();
            }
            return ExitCodes.OK;
        }
        CountDownLatch stopped = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            sim.close();
            if (broker != null) {
                broker.close();
            }
            stopped.countDown();
            Runtime.getRuntime().halt(ExitCodes.OK);
        }, "habla-sim-shutdown"));
        stopped.await();
        return ExitCodes.OK;
    }
}
