package org.habla.sim.scenario;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * The simulated robot of a {@code ros2-base} scenario: two programs of {@code habla-ros2} in the ROS 2
 * environment ({@code ./habla ros2 setup}) — the simulated ROS 2 base (REP-105 topics, the Pioneer's world, teacher,
 * microphone, keyboard and ground truth) and the body that makes it a HABLA body over the interface protocol. Their
 * DDS traffic stays on this machine, in ROS domain {@code 1 + (port offset / 100) mod 100} (or {@code ROS_DOMAIN_ID}
 * when set), so runs beside each other do not hear each other.
 */
final class Ros2Base {

    /** Where the body listens for the daemon, before the port offset ({@code config/ros2-base.json}'s robot). */
    static final int BODY_PORT = 8120;
    private static final long ENV_CHECK_S = 30;
    /** Sim seconds between two sendings of a held motion by the body. */
    private static final double RESEND_SIM_S = 0.2;

    private Ros2Base() {
    }

    /** Starts the simulated base and the body; the simulated base is the first child. */
    static List<Children.Child> start(Children children, Path home, Path reportDir, String world, double speed, long seed,
            int portOffset, int truthPort) throws IOException {
        String python = python(home);
        Map<String, String> env = Map.of(
                "PYTHONPATH", home.resolve("clients/python/src") + ":" + home.resolve("clients/python-ros2/src"),
                "ROS_DOMAIN_ID", domain(portOffset), "ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST",
                "PYTHONUNBUFFERED", "1");
        Children.Child sim = children.start("simulator", List.of(python, "-m", "habla_ros2", "sim-base", "--world", world,
                "--speed", ScenarioRunner.fmt(speed), "--seed", "" + seed, "--teacher", "off", "--truth-port", "" + truthPort,
                "--mic-port", "" + (8110 + portOffset), "--keys-port", "" + (8111 + portOffset)), env, home,
                reportDir.resolve("simulator.log"));
        // A base's controller stops when commands stop coming (the simulated one after 0.5 s of sim time): the body
        // sends a held motion again at 5 Hz of sim time, whatever the speed.
        Children.Child body = children.start("body", List.of(python, "-m", "habla_ros2", "body", "--listen",
                "127.0.0.1:" + (BODY_PORT + portOffset), "--cmd-period", ScenarioRunner.fmt(RESEND_SIM_S / speed)), env,
                home, reportDir.resolve("body.log"));
        return List.of(sim, body);
    }

    /** The ROS domain of a run: ROS_DOMAIN_ID when set, else one from the port offset. */
    static String domain(int portOffset) {
        String set = System.getenv("ROS_DOMAIN_ID");
        return set != null && !set.isBlank() ? set : "" + (1 + Math.floorMod(portOffset / 100, 100));
    }

    /** The ROS 2 environment's python, or an error naming the command that makes it. */
    static String python(Path home) throws IOException {
        Process p = new ProcessBuilder(home.resolve("clients/ros2-env.sh").toString(), "python").start();
        try {
            if (!p.waitFor(ENV_CHECK_S, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new IOException("clients/ros2-env.sh did not answer within " + ENV_CHECK_S + " s");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while looking for the ROS 2 environment", e);
        }
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        if (p.exitValue() != 0 || !Files.isExecutable(Path.of(out))) {
            throw new IOException(err.isEmpty() ? "no ROS 2 environment; make it with ./habla ros2 setup" : err);
        }
        return out;
    }
}
