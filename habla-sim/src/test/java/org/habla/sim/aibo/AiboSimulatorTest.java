package org.habla.sim.aibo;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.time.Duration;
import java.util.HashMap;
import java.util.Map;
import javax.imageio.ImageIO;
import org.habla.config.ParamsJson;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.drivers.tekkotsu.TekkotsuDriverProvider;
import org.habla.drivers.tekkotsu.TekkotsuParams;
import org.habla.sample.AudioChunk;
import org.habla.sample.ImageFrame;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.habla.sim.world.Pose2;
import org.habla.sim.world.TruthClient;
import org.habla.sim.world.World;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The simulated Aibo in its arena, driven by HABLA's real tekkotsu driver and watched through the ground truth. */
class AiboSimulatorTest {

    private static final Duration LIMIT = Duration.ofSeconds(20);
    private static final double SPEED = 8;
    /** Ground-truth lines to look through for one that matches: 500 s of sim time, a minute of real time. */
    private static final int LINES = 5_000;

    private final RecordingSink sink = new RecordingSink();
    private final Map<String, DriverLink> links = new HashMap<>();
    private AiboSimulator sim;
    private TruthClient truth;

    @AfterEach
    void closeAll() throws IOException {
        links.values().forEach(DriverLink::close);
        if (truth != null) {
            truth.close();
        }
        if (sim != null) {
            sim.close();
        }
    }

    /** The arena with the teacher away, the driver connected with every server (the walk re-sent often: 8× time). */
    private void start(String extraParams) throws IOException {
        sim = new AiboSimulator(AiboSimulator.Options.defaults(World.builtIn("aibo-arena")).onFreePorts()
                .withSpeed(SPEED).withSeed(3).withTeacher(false));
        sim.start();
        truth = new TruthClient(sim.truthPort());
        TekkotsuPorts p = sim.ports();
        String params = """
                {"worldStatePort": %d, "microphonePort": %d, "cameraPort": %d, "walkPort": %d, "headPort": %d,
                 "speakerPort": %d, "eStopPort": %d, "controllerPort": %d, "walkResendMs": 100%s}"""
                .formatted(p.worldState(), p.microphone(), p.rawCam(), p.walk(), p.head(), p.speaker(), p.eStop(),
                        p.controller(), extraParams);
        Driver driver = new TekkotsuDriverProvider().create(InterfaceAddress.parse("127.0.0.1"),
                ParamsJson.of(TekkotsuParams.class, params));
        for (Connection c : driver.connections()) {
            links.put(c.name(), new DriverLink(c, sink));
        }
        assertThat(DriverLink.await(LIMIT, () -> links.get("walk").up() && links.get("head").up()
                && sink.on("ir").size() > 2)).as("servers switched on, world state flowing").isTrue();
    }

    private void place(double x, double y, double theta) throws IOException {
        assertThat(op("{\"op\":\"reset\",\"robot\":{\"xM\":%s,\"yM\":%s,\"thetaRad\":%s}}"
                .formatted(x, y, theta)).has("ok")).isTrue();
    }

    /** Sends a ground-truth operation and returns its reply, skipping however many truth lines came first. */
    private JsonNode op(String json) throws IOException {
        truth.send(json);
        return truth.next(n -> !n.has("t"), LINES);
    }

    private boolean send(String link, String channel, VectorValue v) {
        try {
            return links.get(link).write(channel, v);
        } catch (IOException e) {
            return false;
        }
    }

    @Test
    void aWalkCommandMovesTheRobotAsCommandedInSimTime() throws Exception {
        start("");
        assertThat(DriverLink.await(LIMIT, () -> !sim.ers7().eStopped())).isTrue();
        place(0.5, 1.25, 0);
        assertThat(send("walk", "walk", VectorValue.of(0.09, 0, 0))).isTrue();
        JsonNode a = truth.next(n -> n.has("t") && n.path("aibo").path("walk").path("forwardMps").asDouble() > 0, LINES);
        a = truth.next(n -> n.has("t"), 10); // past the 0.3 s ramp up
        a = truth.next(n -> n.has("t"), 10);
        a = truth.next(n -> n.has("t"), 10);
        double ta = a.get("t").asDouble();
        JsonNode b = truth.next(n -> n.has("t") && n.get("t").asDouble() >= ta + 1.5, LINES);
        double dt = b.get("t").asDouble() - ta;
        double dx = b.path("robot").path("xM").asDouble() - a.path("robot").path("xM").asDouble();
        assertThat(dx / dt).as("forward speed, m/s").isCloseTo(0.09, within(0.005));
        assertThat(b.path("robot").path("yM").asDouble()).isCloseTo(1.25, within(0.005));

        assertThat(send("walk", "walk", VectorValue.of(0, 0, 0.9))).isTrue();
        JsonNode c = truth.next(n -> n.has("t") && n.path("aibo").path("walk").path("rotateRadps").asDouble() > 0, LINES);
        c = truth.next(n -> n.has("t"), 10);
        c = truth.next(n -> n.has("t"), 10);
        double tc = c.get("t").asDouble();
        JsonNode d = truth.next(n -> n.has("t") && n.get("t").asDouble() >= tc + 0.5, LINES);
        double turned = Pose2.normalize(d.path("robot").path("thetaRad").asDouble()
                - c.path("robot").path("thetaRad").asDouble());
        assertThat(turned / (d.get("t").asDouble() - tc)).as("turn rate, rad/s").isCloseTo(0.9, within(0.05));
    }

    @Test
    void theEmergencyStopHoldsTheRobotStill() throws Exception {
        start(", \"releaseEStop\": false");
        place(0.5, 1.25, 0);
        assertThat(send("walk", "walk", VectorValue.of(0.18, 0, 0))).isTrue();
        JsonNode a = truth.truth();
        JsonNode b = truth.next(n -> n.has("t") && n.get("t").asDouble() >= a.get("t").asDouble() + 1.0, LINES);
        assertThat(b.path("aibo").path("eStop").asBoolean()).isTrue();
        assertThat(b.path("robot").path("xM").asDouble()).isCloseTo(0.5, within(1e-6));
    }

    @Test
    void infraredReadingsMatchTheRayCastWithinNoise() throws Exception {
        start("");
        assertThat(DriverLink.await(LIMIT, () -> !sim.ers7().eStopped())).isTrue();
        // level head, facing the wall at x = 2.5: the far sensor sees it 1.1 m away, the near one nothing
        place(1.25, 1.25, 0);
        checkInfrared(new Ers7Body.HeadPose(0, 0, 0), new double[] {0.5, 1.1, 0.139});
        // head panned fully left and nodded down a little: the far sensor now sees the floor
        assertThat(send("head", "head", VectorValue.of(0, Math.toRadians(88), Math.toRadians(-10)))).isTrue();
        Ers7Body.HeadPose turned = new Ers7Body.HeadPose(0, Math.toRadians(88), Math.toRadians(-10));
        assertThat(DriverLink.await(LIMIT, () -> {
            RecordValue h = (RecordValue) sink.latest("head-pose");
            return Math.abs(h.number("panRad") - turned.panRad()) < 1e-4
                    && Math.abs(h.number("nodRad") - turned.nodRad()) < 1e-4;
        })).isTrue();
        double[] expected = Infrared.exact(World.builtIn("aibo-arena"), World.builtIn("aibo-arena").target(),
                new Pose2(1.25, 1.25, 0), turned);
        assertThat(expected[1]).as("the floor, 0.2 m / sin 10°").isCloseTo(1.152, within(0.01));
        checkInfrared(turned, new double[] {0.5, expected[1], 0.139});
    }

    private void checkInfrared(Ers7Body.HeadPose head, double[] expected) throws Exception {
        double[] exact = Infrared.exact(World.builtIn("aibo-arena"), World.builtIn("aibo-arena").target(),
                new Pose2(1.25, 1.25, 0), head);
        for (int i = 0; i < 3; i++) {
            double clipped = Math.max(Infrared.MIN_M[i], Math.min(Infrared.MAX_M[i], exact[i]));
            assertThat(clipped).isCloseTo(expected[i], within(0.01));
        }
        int before = sink.on("ir").size();
        assertThat(DriverLink.await(LIMIT, () -> sink.on("ir").size() >= before + 20)).isTrue();
        var recent = sink.on("ir").subList(before + 10, before + 20);
        for (int i = 0; i < 3; i++) {
            double sum = 0;
            for (var r : recent) {
                double v = ((VectorValue) r).get(i);
                double sigma = Infrared.NOISE_FLOOR_M + Infrared.NOISE_FRACTION * expected[i];
                assertThat(v).as("sensor " + i).isCloseTo(expected[i], within(5 * sigma));
                sum += v;
            }
            assertThat(sum / recent.size()).as("mean of sensor " + i).isCloseTo(expected[i],
                    within(2 * (Infrared.NOISE_FLOOR_M + Infrared.NOISE_FRACTION * expected[i])));
        }
    }

    @Test
    void touchingTheRobotShowsOnItsButtons() throws Exception {
        start("");
        int before = sink.on("buttons").size();
        assertThat(op("{\"op\":\"touch\",\"sensor\":\"back\"}").has("ok")).isTrue();
        assertThat(DriverLink.await(LIMIT, () -> pressedSince(before, "backMiddle"))).isTrue();
        assertThat(pressedSince(before, "headTouch")).isFalse();
        int second = sink.on("buttons").size();
        assertThat(op("{\"op\":\"touch\",\"sensor\":\"head\"}").has("ok")).isTrue();
        assertThat(DriverLink.await(LIMIT, () -> pressedSince(second, "headTouch"))).isTrue();
        assertThat(op("{\"op\":\"touch\",\"sensor\":\"tail\"}").path("error").asText()).contains("head");
        int third = sink.on("buttons").size();
        assertThat(op("{\"op\":\"reward\",\"value\":-1}").has("ok")).isTrue();
        assertThat(DriverLink.await(LIMIT, () -> pressedSince(third, "headTouch")))
                .as("pain is a touch on the head").isTrue();
    }

    /** Whether a buttons reading after the first {@code from} shows {@code button} pressed (a touch lasts 0.5 s of sim time). */
    private boolean pressedSince(int from, String button) {
        var all = sink.on("buttons");
        return all.subList(Math.min(from, all.size()), all.size()).stream()
                .anyMatch(b -> ((RecordValue) b).number(button) > 0.5);
    }

    @Test
    void theTeachersSpokenCommandReachesTheMicrophone() throws Exception {
        start("");
        assertThat(DriverLink.await(LIMIT, () -> sink.on("audio").size() > 5)).isTrue();
        double quiet = loudest(sink.on("audio").size() - 5);
        int before = sink.on("audio").size();
        JsonNode reply = op("{\"op\":\"say\",\"label\":\"left\"}");
        assertThat(reply.has("ok")).isTrue();
        // Lines the server wrote before the operation took effect may still be on their way: wait for the state.
        JsonNode said = truth.next(n -> n.has("t") && n.path("aibo").path("lastPhrase").asText().equals("turn left"), LINES);
        assertThat(said).as("a ground-truth line with the phrase").isNotNull();
        assertThat(DriverLink.await(LIMIT, () -> loudest(before) > 10 * quiet)).as("an utterance over the noise")
                .isTrue();
    }

    @Test
    void aPresentTeacherCommandsByVoiceAndRewardsByTouch() throws Exception {
        start("");
        place(0.6, 0.6, 0);
        assertThat(op("{\"op\":\"teacher\",\"present\":true}").has("ok")).isTrue();
        // the robot stands still, so the first command is judged a failure: pain, a touch on the head
        JsonNode judged = truth.next(n -> n.has("t") && !n.path("teacher").path("lastReward").isNull(), LINES);
        assertThat(judged.path("teacher").path("lastCommand").asText()).isIn("forward", "left", "right");
        assertThat(judged.path("teacher").path("lastReward").asDouble()).isEqualTo(-1.0);
        assertThat(judged.path("aibo").path("lastPhrase").asText()).isIn("go forward", "turn left", "turn right");
        assertThat(DriverLink.await(LIMIT, () -> pressedSince(0, "headTouch"))).isTrue();
        assertThat(loudest(0)).as("the spoken command on the microphone").isGreaterThan(0.02);
    }

    private double loudest(int from) {
        double max = 0;
        var audio = sink.on("audio");
        for (int i = Math.max(0, from); i < audio.size(); i++) {
            max = Math.max(max, TekkotsuServersTest.rms((AudioChunk) audio.get(i)));
        }
        return max;
    }

    @Test
    void theCameraShowsTheBallWhereThePinholeProjectionPutsIt() throws Exception {
        start("");
        World arena = World.builtIn("aibo-arena");
        var ball = arena.target();
        // 0.6 m from the ball, facing a little to its right so that it sits left of the centre
        double heading = Math.atan2(ball.yM() - 1.3, ball.xM() - 1.5) - 0.15;
        place(1.5, 1.3, heading);
        int before = sink.on("camera").size();
        assertThat(DriverLink.await(LIMIT, () -> sink.on("camera").size() > before + 3)).isTrue();
        ImageFrame frame = (ImageFrame) sink.latest("camera");
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(frame.data()));
        double[] seen = TekkotsuServersTest.pinkCentroid(image);
        Ers7Geometry.Ray nose = Ers7Geometry.nose(new Pose2(1.5, 1.3, heading), new Ers7Body.HeadPose(0, 0, 0));
        double[] expected = new PinholeCamera(104, 80).project(new CameraView.CameraPose(nose.xM(), nose.yM(),
                nose.zM(), nose.yawRad(), nose.pitchRad()), ball.xM(), ball.yM(), ball.radiusM());
        assertThat(seen[2]).as("pink pixels").isGreaterThan(4);
        assertThat(seen[0]).isCloseTo(expected[0], within(1.5));
        assertThat(seen[1]).isCloseTo(expected[1], within(1.5));
        assertThat(expected[0]).as("left of the centre column").isLessThan(52 - 5);
    }
}
