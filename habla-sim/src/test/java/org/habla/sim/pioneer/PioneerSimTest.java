package org.habla.sim.pioneer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.util.Random;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.habla.sim.world.Pose2;
import org.habla.sim.world.TruthClient;
import org.habla.sim.world.World;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** HABLA's real Pioneer driver against the simulated Pioneer, over loopback, at ten times real time. */
class PioneerSimTest {

    private static final double SPEED = 10;
    /** The driver's PULSE period, real ms: half a sim second, as the real driver's 500 ms at real time. */
    private static final int KEEP_ALIVE_MS = 50;
    private static final long WAIT_MS = 10_000;

    private final World room = World.builtIn("pioneer-room");
    private PioneerSim sim;
    private TruthClient truth;

    @BeforeEach
    void start() throws IOException {
        sim = PioneerSim.start(PioneerSimOptions.forTest(room, SPEED));
        truth = new TruthClient(sim.truthPort());
    }

    @AfterEach
    void stop() throws IOException {
        truth.close();
        sim.close();
    }

    private DriverHarness connect() throws IOException, InterruptedException {
        DriverHarness h = new DriverHarness(sim.arcosPort(), KEEP_ALIVE_MS);
        h.await("status", RecordValue.class, s -> s.get("motorsEnabled").booleanValue(), WAIT_MS);
        return h;
    }

    private void placeRobot(double x, double y, double theta) throws IOException {
        JsonNode reply = truth.op("{\"op\":\"reset\",\"robot\":{\"xM\":" + x + ",\"yM\":" + y + ",\"thetaRad\":" + theta + "}}");
        assertThat(reply.has("ok")).as("reset reply %s", reply).isTrue();
    }

    private void waitSim(double seconds) throws InterruptedException {
        assertThat(sim.clock().awaitSimTime(sim.clock().nowS() + seconds, WAIT_MS)).isTrue();
    }

    private static RecordValue odometry(DriverHarness h) throws InterruptedException {
        return h.await("odometry", RecordValue.class, o -> true, WAIT_MS);
    }

    @Test
    void theDriverHandshakesWithTheSimulatedP2dxAndEnablesItsMotors() throws Exception {
        try (DriverHarness h = connect()) {
            assertThat(h.robotInfo()).singleElement().satisfies(info -> {
                assertThat(info.path("name").asText()).isEqualTo("HABLA-sim");
                assertThat(info.path("class").asText()).isEqualTo("Pioneer");
                assertThat(info.path("subclass").asText()).isEqualTo("p2dx");
            });
            RecordValue status = h.await("status", RecordValue.class, s -> s.get("sonarOn").booleanValue(), WAIT_MS);
            assertThat(status.get("motorsEnabled").booleanValue()).isTrue();
            assertThat(h.await("battery", org.habla.sample.NumberValue.class, b -> true, WAIT_MS).value()).isEqualTo(13.0);
            assertThat(h.malformed()).isEmpty();
        }
    }

    @Test
    void odometryFollowsAVelocityCommandOverSimTime() throws Exception {
        try (DriverHarness h = connect()) {
            Pose2 start = sim.scene().body().pose();
            h.command("motion", VectorValue.of(0.3, 0));
            RecordValue cruising = h.await("odometry", RecordValue.class,
                    o -> Math.abs(o.number("vMps") - 0.3) < 1e-3, WAIT_MS);
            assertThat(cruising.number("wRadps")).isCloseTo(0, within(1e-3));
            waitSim(2);
            h.command("motion", VectorValue.of(0, 0));
            RecordValue stopped = h.await("odometry", RecordValue.class,
                    o -> o.number("vMps") == 0 && o.number("xM") > 0.5, WAIT_MS);
            waitSim(0.3);
            Pose2 end = sim.scene().body().pose();
            RecordValue odo = odometry(h);
            // Odometry tells where the robot really went, to the SIP's 0.84 mm resolution.
            assertThat(odo.number("xM")).isCloseTo(end.xM() - start.xM(), within(0.005));
            assertThat(odo.number("yM")).isCloseTo(end.yM() - start.yM(), within(0.005));
            assertThat(stopped.number("thetaRad")).isCloseTo(0, within(0.002));
            // The ramp up at 0.3 m/s² (0.15 m), at least 2 s cruising at 0.3 m/s (0.6 m), braking at 0.6 m/s²
            // (0.075 m); how much more depends on the test's own latency.
            assertThat(odo.number("xM")).isGreaterThan(0.15 + 0.6 + 0.075 - 0.01);
        }
    }

    @Test
    void backingUpFromTheOriginRollsThe15BitPositionOverAndOdometryStaysContinuous() throws Exception {
        try (DriverHarness h = connect()) {
            Pose2 start = sim.scene().body().pose();
            h.command("motion", VectorValue.of(-0.25, 0));
            h.await("odometry", RecordValue.class, o -> o.number("xM") < -0.3, WAIT_MS);
            h.command("motion", VectorValue.of(0, 0));
            h.await("odometry", RecordValue.class, o -> o.number("vMps") == 0, WAIT_MS);
            waitSim(0.3);
            // Raw XPOS went 0 → 0x7FFF and below; the driver reads a negative, continuous position.
            assertThat(odometry(h).number("xM"))
                    .isCloseTo(sim.scene().body().pose().xM() - start.xM(), within(0.005))
                    .isLessThan(-0.3);
        }
    }

    @Test
    void odometryFollowsARotationCommand() throws Exception {
        try (DriverHarness h = connect()) {
            h.command("motion", VectorValue.of(0, 0.5));
            RecordValue turning = h.await("odometry", RecordValue.class,
                    o -> Math.abs(o.number("wRadps") - 0.5) < 0.01, WAIT_MS);
            assertThat(turning.number("leftMps")).isNegative();
            assertThat(turning.number("rightMps")).isPositive();
            waitSim(1);
            h.command("motion", VectorValue.of(0, 0));
            h.await("odometry", RecordValue.class, o -> o.number("wRadps") == 0, WAIT_MS);
            waitSim(0.3);
            assertThat(odometry(h).number("thetaRad"))
                    .isCloseTo(sim.scene().body().pose().thetaRad() - room.robotStart().thetaRad(), within(0.003))
                    .isGreaterThan(0.4);
        }
    }

    @Test
    void aRobotCarriedElsewhereByAResetKeepsItsOdometry() throws Exception {
        try (DriverHarness h = connect()) {
            h.command("motion", VectorValue.of(0.3, 0));
            h.await("odometry", RecordValue.class, o -> o.number("xM") > 0.2, WAIT_MS);
            h.command("motion", VectorValue.of(0, 0));
            h.await("odometry", RecordValue.class, o -> o.number("vMps") == 0, WAIT_MS);
            waitSim(0.3);
            RecordValue before = odometry(h);
            placeRobot(3, 3, 1.0);
            waitSim(0.5);
            RecordValue after = odometry(h);
            assertThat(after.number("xM")).isCloseTo(before.number("xM"), within(0.002));
            assertThat(after.number("yM")).isCloseTo(before.number("yM"), within(0.002));
            assertThat(after.number("thetaRad")).isCloseTo(before.number("thetaRad"), within(0.002));
            // Driving on from the new place continues the old odometry along the old heading.
            h.command("motion", VectorValue.of(0.3, 0));
            RecordValue onward = h.await("odometry", RecordValue.class,
                    o -> o.number("xM") > before.number("xM") + 0.2, WAIT_MS);
            assertThat(onward.number("yM")).isCloseTo(before.number("yM"), within(0.005));
            Pose2 p = sim.scene().body().pose();
            assertThat(Math.hypot(p.xM() - 3, p.yM() - 3)).isGreaterThan(0.19);
            assertThat(p.thetaRad()).isCloseTo(1.0, within(0.002));
            h.command("motion", VectorValue.of(0, 0));
        }
    }

    @Test
    void sonarRangesMatchTheRayCastWorldWithinTheNoise() throws Exception {
        placeRobot(1.2, 4.8, 0.3);
        try (DriverHarness h = connect()) {
            waitSim(0.5); // a full ring fired after the reset
            VectorValue sonar = h.await("sonar", VectorValue.class, v -> v.size() == 16, WAIT_MS);
            waitSim(0.4);
            sonar = h.await("sonar", VectorValue.class, v -> v.size() == 16, WAIT_MS);
            Pose2 robot = sim.scene().body().pose();
            int near = 0;
            for (int i = 0; i < 16; i++) {
                double expected = expectedRange(robot, P2dx.SONARS.get(i));
                assertThat(sonar.get(i)).as("sonar %d", i).isCloseTo(expected, within(0.05));
                near += expected < 2 ? 1 : 0;
            }
            assertThat(near).as("sonars seeing a wall within 2 m").isGreaterThanOrEqualTo(6);
        }
    }

    /** The nearest echo in a 30° beam, cast here with five rays like the robot's model claims to. */
    private double expectedRange(Pose2 robot, P2dx.Transducer t) {
        Pose2 at = robot.moved(t.xM(), t.yM(), t.thetaRad());
        double best = 5.0;
        for (double offDeg = -15; offDeg <= 15; offDeg += 7.5) {
            best = Math.min(best, room.rangeAlong(at.xM(), at.yM(), at.thetaRad() + Math.toRadians(offDeg), 5.0));
        }
        return Math.max(0.1, best);
    }

    @Test
    void drivingIntoAWallStallsTheWheelsAndPressesTheFrontBumper() throws Exception {
        placeRobot(5.3, 3.0, 0);
        try (DriverHarness h = connect()) {
            h.command("motion", VectorValue.of(0.3, 0));
            RecordValue stall = h.await("stall", RecordValue.class,
                    s -> s.get("left").booleanValue() && s.get("right").booleanValue(), WAIT_MS);
            assertThat(stall).isNotNull();
            RecordValue bumpers = h.await("bumpers", RecordValue.class, b -> b.get("frontHit").booleanValue(), WAIT_MS);
            assertThat(bumpers.get("front").get(2).booleanValue()).as("the middle front bumper").isTrue();
            assertThat(bumpers.get("rearHit").booleanValue()).isFalse();
            assertThat(truth.next(n -> n.has("t") && n.get("stalled").booleanValue(), 50).at("/robot/xM").doubleValue())
                    .isCloseTo(6 - 0.25, within(0.002));
            h.command("motion", VectorValue.of(-0.2, 0));
            h.await("stall", RecordValue.class, s -> !s.get("left").booleanValue(), WAIT_MS);
            h.await("odometry", RecordValue.class, o -> o.number("vMps") < -0.1, WAIT_MS);
        }
    }

    @Test
    void theWatchdogStopsTheRobotAfterTwoSecondsOfSilenceAndTheNextPacketResumes() throws Exception {
        try (DriverHarness h = connect()) {
            h.command("motion", VectorValue.of(0.3, 0));
            h.await("odometry", RecordValue.class, o -> o.number("vMps") > 0.29, WAIT_MS);
            h.keepAlive(false);
            double silentFrom = sim.clock().nowS(); // read first: the last packet arrives after it
            h.pulse();
            // Follow the robot in sim time through the ground truth, immune to the test's own latency.
            java.util.List<double[]> track = new java.util.ArrayList<>();
            while (track.isEmpty() || track.get(track.size() - 1)[0] < silentFrom + 4.5) {
                JsonNode line = truth.next(n -> n.has("t") && n.get("t").doubleValue() >= silentFrom, 1_000);
                track.add(new double[] {line.get("t").doubleValue(), line.at("/robot/xM").doubleValue()});
            }
            for (int i = 1; i < track.size(); i++) {
                double t = track.get(i)[0] - silentFrom;
                double speed = (track.get(i)[1] - track.get(i - 1)[1]) / (track.get(i)[0] - track.get(i - 1)[0]);
                if (t > 0.2 && t < 1.7) {
                    assertThat(speed).as("speed %.2f s into the silence", t).isCloseTo(0.3, within(0.01));
                }
                if (t > 3.8) { // tripped 2 s after the last packet, then 0.5 s of braking, plus the test's lag
                    assertThat(speed).as("speed %.2f s into the silence", t).isZero();
                }
            }
            assertThat(sim.scene().body().stalled()).isFalse();
            double stoppedAt = odometry(h).number("xM");
            waitSim(0.5);
            assertThat(odometry(h).number("xM")).isCloseTo(stoppedAt, within(0.002));
            h.pulse();
            h.await("odometry", RecordValue.class, o -> o.number("vMps") > 0.29, WAIT_MS);
        }
    }

    @Test
    void aRobotLeftDrivingByAVanishedClientStaysStillWhenTheDriverConnectsAgain() throws Exception {
        DriverHarness first = connect();
        first.command("motion", VectorValue.of(-0.2, 0.3));
        first.await("odometry", RecordValue.class, o -> o.number("vMps") < -0.15, WAIT_MS);
        first.vanish();
        waitSim(2.5); // the controller's watchdog has stopped it; its set-points are still there
        try (DriverHarness second = connect()) {
            // The handshake's SYNC0 itself resumes the old set-points until the CLOSE a moment later (as the
            // firmware does); what is left of that brakes within 0.3 s. From then on nothing may move.
            JsonNode connected = truthAt(sim.clock().nowS() + 0.3);
            JsonNode later = truthAt(connected.get("t").doubleValue() + 1.5);
            assertThat(Math.hypot(later.at("/robot/xM").asDouble() - connected.at("/robot/xM").asDouble(),
                    later.at("/robot/yM").asDouble() - connected.at("/robot/yM").asDouble()))
                    .as("the driver's STOP came before its ENABLE: the old motion did not resume").isLessThan(0.002);
            assertThat(Math.abs(later.at("/robot/thetaRad").asDouble() - connected.at("/robot/thetaRad").asDouble()))
                    .isLessThan(0.002);
        }
    }

    /** The first ground-truth line at or after sim time {@code t}. */
    private JsonNode truthAt(double t) throws IOException {
        return truth.next(n -> n.has("t") && n.get("t").doubleValue() >= t, 100_000);
    }

    @Test
    void aNewClientConnectsAfterOneVanishesAndGarbageHurtsNothing() throws Exception {
        DriverHarness first = connect();
        first.command("motion", VectorValue.of(0.2, 0));
        first.await("odometry", RecordValue.class, o -> o.number("vMps") > 0.15, WAIT_MS);
        first.vanish();
        try (Socket rude = new Socket(InetAddress.getLoopbackAddress(), sim.arcosPort())) {
            OutputStream out = rude.getOutputStream();
            byte[] noise = new byte[300];
            new Random(7).nextBytes(noise);
            out.write(noise);
            out.write(new byte[] {(byte) 0xFA, (byte) 0xFB, 0x06, 0x0B, 0x3B}); // a VEL cut short
            out.flush();
        }
        waitSim(2.5); // the watchdog has stopped the abandoned robot meanwhile
        try (DriverHarness second = connect()) {
            assertThat(second.robotInfo()).hasSize(1);
            RecordValue odo = second.await("odometry", RecordValue.class, o -> o.number("vMps") == 0, WAIT_MS);
            assertThat(odo.number("xM")).isCloseTo(0, within(0.01)); // a new session, a new odometry origin
            second.command("motion", VectorValue.of(0, -0.4));
            second.await("odometry", RecordValue.class, o -> o.number("wRadps") < -0.35, WAIT_MS);
        }
    }
}
