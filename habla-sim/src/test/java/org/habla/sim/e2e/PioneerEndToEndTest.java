package org.habla.sim.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.Timeout;

/**
 * The Pioneer set-up end to end: the simulated Pioneer behind its ARCOS, microphone and keyboard
 * sockets, the daemon with config/pioneer.json in its own JVM, and a Python control client on the
 * contract's sockets. The world is the open hall; the time scale is 2.
 */
@Timeout(300)
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class PioneerEndToEndTest {

    static SimulatedDeployment rig;

    @BeforeAll
    static void start() throws Exception {
        Path dir = Files.createDirectories(Path.of("target/e2e/pioneer"));
        // An action held for 20 s, so only the motion watchdog can stop a silent client's robot.
        rig = new SimulatedDeployment("pioneer", "pioneer-hall", 2, dir, config -> {
            for (JsonNode m : config.path("methods")) {
                if (m.path("id").asText().equals("action")) {
                    ((ObjectNode) m.path("params")).put("durationMs", 20_000);
                }
            }
        });
        rig.startSimulator();
        rig.startDaemon();
        rig.awaitReady(60_000);
    }

    @AfterAll
    static void stop() throws Exception {
        if (rig != null) {
            rig.close();
        }
    }

    @Test
    @Order(1)
    void theDistanceAndAngleSocketReportsTheObjectWithinFifteenCentimetresAndTenDegrees() throws Exception {
        // The object (radius 0.15 m) stands at (7, 7) in a 14 m hall.
        double[][] poses = {{5.5, 7.0, 0.0}, {6.0, 6.0, 0.3}, {7.4, 5.6, 2.2}, {8.0, 7.6, -2.0}};
        for (double[] p : poses) {
            rig.place(p[0], p[1], p[2]);
            rig.after(1.5);   // a full sonar cycle
            List<JsonNode> samples = rig.probe(30_000, "sample", "" + rig.port("distance_angle"), "3", "10");
            JsonNode truth = rig.truth.latest();
            assertThat(samples).hasSize(3);
            JsonNode v = samples.get(2).path("value");
            assertThat(v.path("seen").asBoolean()).as("object seen from (%s, %s)", p[0], p[1]).isTrue();
            assertThat(Math.abs(v.path("distanceM").asDouble() - truth.path("distanceM").asDouble()))
                    .as("distance from (%s, %s): got %s, truth %s", p[0], p[1], v, truth.path("distanceM"))
                    .isLessThanOrEqualTo(0.15);
            assertThat(Math.abs(SimulatedDeployment.angleDiff(v.path("angleRad").asDouble(), truth.path("angleRad").asDouble())))
                    .as("angle from (%s, %s): got %s, truth %s", p[0], p[1], v, truth.path("angleRad"))
                    .isLessThanOrEqualTo(Math.toRadians(10));
        }
    }

    @Test
    @Order(2)
    void anActionMovesTheRobotTheRightWay() throws Exception {
        JsonNode before = rig.place(3.0, 3.0, 0.0);
        rig.probe(20_000, "act", "" + rig.port("action"), "forward", "1.0");
        rig.probe(20_000, "act", "" + rig.port("action"), "stop", "0.2");
        JsonNode after = rig.after(0.5);
        double dx = after.path("robot").path("xM").asDouble() - before.path("robot").path("xM").asDouble();
        assertThat(dx).as("drove forward along +x").isGreaterThan(0.1);
        assertThat(Math.abs(after.path("robot").path("yM").asDouble() - 3.0)).isLessThan(0.05);

        before = rig.truth.latest();
        rig.probe(20_000, "act", "" + rig.port("action"), "right", "1.0");
        rig.probe(20_000, "act", "" + rig.port("action"), "stop", "0.2");
        after = rig.after(0.5);
        double turned = SimulatedDeployment.angleDiff(after.path("robot").path("thetaRad").asDouble(),
                before.path("robot").path("thetaRad").asDouble());
        assertThat(turned).as("turned right (clockwise)").isLessThan(-0.3);
    }

    @Test
    @Order(3)
    void whenTheClientGoesSilentTheRobotStopsWithinTheWatchdogTime() throws Exception {
        rig.place(3.0, 10.0, 0.0);
        double watchdogS = 3.0;   // config/pioneer.json: safety.watchdogMs
        // The client writes forward (held 20 s by this test's config) and stays connected but silent.
        Process client = rig.probeAsync("act", "" + rig.port("action"), "forward", "30");
        try {
            // Measured from the write, not from the start of a Python process on a busy machine.
            String wrote = new java.io.BufferedReader(new java.io.InputStreamReader(client.getInputStream(),
                    java.nio.charset.StandardCharsets.UTF_8)).readLine();
            assertThat(wrote).as("the client says it wrote").contains("\"wrote\"");
            JsonNode moving = rig.after(1.0);
            double x1 = moving.path("robot").path("xM").asDouble();
            JsonNode later = rig.after(0.5);
            assertThat(later.path("robot").path("xM").asDouble() - x1).as("moving before the watchdog").isGreaterThan(0.02);
            // Past the watchdog time plus the robot's braking: it must stand still.
            JsonNode stopped = rig.after(watchdogS + 1.0);
            JsonNode still = rig.after(1.0);
            assertThat(Math.abs(still.path("robot").path("xM").asDouble() - stopped.path("robot").path("xM").asDouble()))
                    .as("stands still once the watchdog stopped it").isLessThan(0.01);
            assertThat(stopped.path("t").asDouble() - moving.path("t").asDouble() + 1.0).isLessThan(watchdogS + 3.0);
        } finally {
            client.destroyForcibly();
        }
    }

    @Test
    @Order(4)
    void theDaemonSurvivesTheSimulatorBeingKilledAndRestarted() throws Exception {
        rig.killSimulator();
        assertThat(rig.daemon.alive()).isTrue();
        rig.startSimulator();
        rig.place(5.5, 7.0, 0.0);
        long end = System.nanoTime() + 60_000_000_000L;
        JsonNode v = null;
        while (System.nanoTime() < end) {
            rig.after(1.0);
            List<JsonNode> s = rig.probe(30_000, "sample", "" + rig.port("distance_angle"), "2", "10");
            v = s.isEmpty() ? null : s.get(s.size() - 1);
            if (v != null && !v.path("stale").asBoolean() && v.path("value").path("seen").asBoolean()
                    && Math.abs(v.path("value").path("distanceM").asDouble() - rig.truth.latest().path("distanceM").asDouble()) < 0.15) {
                break;
            }
        }
        assertThat(v).isNotNull();
        assertThat(v.path("stale").asBoolean()).isFalse();
        assertThat(Math.abs(v.path("value").path("distanceM").asDouble() - rig.truth.latest().path("distanceM").asDouble()))
                .as("fresh readings from the restarted robot").isLessThan(0.15);
        // And it still drives.
        JsonNode before = rig.truth.latest();
        rig.probe(20_000, "act", "" + rig.port("action"), "back", "1.0");
        rig.probe(20_000, "act", "" + rig.port("action"), "stop", "0.2");
        JsonNode after = rig.after(0.5);
        assertThat(after.path("robot").path("xM").asDouble() - before.path("robot").path("xM").asDouble())
                .as("backs up after the restart").isLessThan(-0.05);
    }
}
