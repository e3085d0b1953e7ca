package org.habla.sim.aibo;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.habla.config.ParamsJson;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.drivers.tekkotsu.TekkotsuDriverProvider;
import org.habla.drivers.tekkotsu.TekkotsuParams;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import org.habla.sample.ImageFrame;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.habla.sim.world.SimClock;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** HABLA's real tekkotsu driver against the simulated Aibo's servers, over loopback. */
class TekkotsuServersTest {

    private static final Duration LIMIT = Duration.ofSeconds(20);
    private static final CameraView.Ball BALL = new CameraView.Ball(1.0, 0.15, 0.1, 0xff50aa);

    private final SimClock clock = new SimClock(4, 0.008);
    private final AiboTime time = new AiboTime(clock);
    private final Ers7Body body = new Ers7Body();
    private final Microphone mic = new Microphone(7);
    private final SpeakerLog said = new SpeakerLog();
    private final RecordingSink sink = new RecordingSink();
    private final List<AutoCloseable> open = new ArrayList<>();
    private final Map<String, DriverLink> links = new HashMap<>();
    private TekkotsuServers servers;

    @AfterEach
    void closeAll() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
    }

    private void start(String extraParams) throws IOException {
        servers = new TekkotsuServers(TekkotsuPorts.ANY_FREE, time, body, mic, said, at -> view());
        open.add(servers);
        clock.add((nowS, dtS) -> body.step(dtS, Math.round(nowS * 1000)));
        clock.start();
        open.add(clock);
        TekkotsuPorts p = servers.ports();
        String params = """
                {"worldStatePort": %d, "microphonePort": %d, "cameraPort": %d, "walkPort": %d, "headPort": %d,
                 "speakerPort": %d, "eStopPort": %d, "controllerPort": %d%s}"""
                .formatted(p.worldState(), p.microphone(), p.rawCam(), p.walk(), p.head(), p.speaker(), p.eStop(),
                        p.controller(), extraParams);
        Driver driver = new TekkotsuDriverProvider().create(InterfaceAddress.parse("127.0.0.1"),
                ParamsJson.of(TekkotsuParams.class, params));
        for (Connection c : driver.connections()) {
            DriverLink link = new DriverLink(c, sink);
            open.add(link);
            links.put(c.name(), link);
        }
    }

    private static CameraView view() {
        List<double[]> walls = List.of(new double[] {-1, -1.5, 3, -1.5}, new double[] {3, -1.5, 3, 1.5},
                new double[] {3, 1.5, -1, 1.5}, new double[] {-1, 1.5, -1, -1.5});
        return new CameraView(walls, 0.5, BALL, new CameraView.CameraPose(0, 0, 0.2, 0, 0));
    }

    @Test
    void theDriverSwitchesTheServersOnAndReadsTheWorldState() throws Exception {
        body.setInfrared(0.31, 1.23, 0.14);
        start("");
        assertThat(DriverLink.await(LIMIT, () -> sink.on("ir").size() >= 3)).isTrue();
        VectorValue ir = (VectorValue) sink.latest("ir");
        assertThat(ir.get(0)).isCloseTo(0.31, within(1e-6));
        assertThat(ir.get(1)).isCloseTo(1.23, within(1e-6));
        assertThat(ir.get(2)).isCloseTo(0.14, within(1e-6));
        assertThat(sink.info).anySatisfy(i -> assertThat(i.path("model").asText()).isEqualTo("ERS-7"));
        assertThat(sink.info).anySatisfy(i -> assertThat(i.path("controllerHellos").asLong()).isEqualTo(1));
        assertThat(DriverLink.await(LIMIT, () -> sink.info.stream().anyMatch(i -> i.has("lastServerStarted"))))
                .as("the controller announces the walk viewer with its port").isTrue();
        assertThat(DriverLink.await(LIMIT, () -> sink.info.stream()
                .anyMatch(i -> i.path("eStop").asText().equals("off")))).isTrue();
        assertThat(sink.malformed).isEmpty();
    }

    @Test
    void buttonsShowATouchWhileItLasts() throws Exception {
        start("");
        assertThat(DriverLink.await(LIMIT, () -> sink.latest("buttons") != null)).isTrue();
        int before = sink.on("buttons").size();
        body.press(Ers7Layout.HEAD_BUTTON, time.nowMs() + 400);
        assertThat(DriverLink.await(LIMIT, () -> sink.on("buttons").stream().skip(before)
                .anyMatch(b -> ((RecordValue) b).number("headTouch") > 0.5))).isTrue();
        assertThat(sink.on("buttons").stream().skip(before)
                .allMatch(b -> ((RecordValue) b).number("backMiddle") == 0)).isTrue();
        assertThat(DriverLink.await(LIMIT, () -> ((RecordValue) sink.latest("buttons")).number("headTouch") == 0))
                .as("released after its time").isTrue();
    }

    @Test
    void walkCommandsSetTheWalkAndTheEmergencyStopHoldsItBack() throws Exception {
        start(", \"eStop\": false, \"walkResendMs\": 200");
        assertThat(DriverLink.await(LIMIT, () -> servers.ports() != null && links.get("walk").up()
                && links.get("walk").sessionCount() > 0 && sink.on("ir").size() > 2)).isTrue();
        assertThat(DriverLink.await(LIMIT, () -> writeWalk(0.09, 0.07, -0.9))).isTrue();
        assertThat(DriverLink.await(LIMIT, () -> body.walkCommands() >= 3)).as("the walk arrived").isTrue();
        assertThat(body.walk(time.nowMs())).as("e-stop on at boot").isEqualTo(Ers7Body.Walk.STILL);

        try (Socket s = new Socket("127.0.0.1", servers.ports().eStop())) {
            s.getOutputStream().write("refresh\nstart\n".getBytes(StandardCharsets.US_ASCII));
            InputStream in = s.getInputStream();
            assertThat(new String(in.readNBytes(7), StandardCharsets.US_ASCII)).isEqualTo("on\noff\n");
            assertThat(DriverLink.await(LIMIT, () -> !body.walk(time.nowMs()).equals(Ers7Body.Walk.STILL))).isTrue();
            Ers7Body.Walk w = body.walk(time.nowMs());
            assertThat(w.forwardMps()).isCloseTo(0.09, within(1e-6));
            assertThat(w.strafeMps()).isCloseTo(0.07, within(1e-6));
            assertThat(w.rotateRadps()).isCloseTo(-0.9, within(1e-6));

            // The answer to the refresh after it says the line before was taken, and not as a stop.
            s.getOutputStream().write("stop\r\nrefresh\n".getBytes(StandardCharsets.US_ASCII));
            assertThat(new String(in.readNBytes(4), StandardCharsets.US_ASCII)).isEqualTo("off\n");
            assertThat(body.eStopped()).as("'stop\\r' is not 'stop'").isFalse();
            s.getOutputStream().write("stop\n".getBytes(StandardCharsets.US_ASCII));
            assertThat(new String(in.readNBytes(3), StandardCharsets.US_ASCII)).isEqualTo("on\n");
            assertThat(body.walk(time.nowMs())).isEqualTo(Ers7Body.Walk.STILL);
        }
    }

    private boolean writeWalk(double forward, double strafe, double rotate) {
        try {
            return links.get("walk").write("walk", VectorValue.of(forward, strafe, rotate));
        } catch (IOException e) {
            return false;
        }
    }

    @Test
    void theWalkStopsThreeSecondsAfterTheLastCommand() throws Exception {
        body.setEStop(false);
        long now = time.nowMs();
        body.walkCommand('f', 0.5f, now);
        assertThat(body.walk(now + 2_900).forwardMps()).isCloseTo(0.09, within(1e-6));
        assertThat(body.walk(now + 3_100)).isEqualTo(Ers7Body.Walk.STILL);
        body.walkCommand('r', 1f, now + 3_200);
        assertThat(body.walk(now + 3_300)).as("the stored forward comes back with the next command")
                .isEqualTo(new Ers7Body.Walk(0.09, 0, 1.8));
    }

    @Test
    void theHeadMovesToItsTargetWithinTheJointLimits() throws Exception {
        start("");
        assertThat(DriverLink.await(LIMIT, () -> links.get("head").up() && !body.eStopped())).isTrue();
        double tilt = -0.5;
        double nod = 0.3;
        assertThat(DriverLink.await(LIMIT, () -> {
            try {
                return links.get("head").write("head", VectorValue.of(tilt, 2.5, nod));
            } catch (IOException e) {
                return false;
            }
        })).isTrue();
        assertThat(DriverLink.await(LIMIT, () -> {
            RecordValue h = (RecordValue) sink.latest("head-pose");
            return h != null && Math.abs(h.number("panRad") - Math.toRadians(88)) < 1e-4;
        })).as("pan clamped at 88°").isTrue();
        RecordValue h = (RecordValue) sink.latest("head-pose");
        assertThat(h.number("tiltRad")).isCloseTo(tilt, within(1e-4));
        assertThat(h.number("nodRad")).isCloseTo(nod, within(1e-4));
    }

    @Test
    void theCameraFrameIsAJpegWithTheBallWhereThePinholeProjectionPutsIt() throws Exception {
        start("");
        assertThat(DriverLink.await(LIMIT, () -> !sink.on("camera").isEmpty())).isTrue();
        ImageFrame frame = (ImageFrame) sink.latest("camera");
        assertThat(frame.encoding()).isEqualTo("jpeg");
        assertThat(frame.width()).isEqualTo(104);
        assertThat(frame.height()).isEqualTo(80);
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(frame.data()));
        assertThat(image.getWidth()).isEqualTo(104);
        double[] centroid = pinkCentroid(image);
        PinholeCamera camera = new PinholeCamera(104, 80);
        double[] expected = camera.project(view().camera(), BALL.xM(), BALL.yM(), BALL.radiusM());
        assertThat(centroid[2]).as("pink pixels").isGreaterThan(20);
        assertThat(centroid[0]).isCloseTo(expected[0], within(1.5));
        assertThat(centroid[1]).isCloseTo(expected[1], within(1.5));
        assertThat(expected[0]).as("ball left of centre").isLessThan(52);
    }

    /** The mean column and row of clearly pink pixels, and their count. */
    static double[] pinkCentroid(BufferedImage image) {
        double su = 0;
        double sv = 0;
        int n = 0;
        for (int v = 0; v < image.getHeight(); v++) {
            for (int u = 0; u < image.getWidth(); u++) {
                int rgb = image.getRGB(u, v);
                int r = (rgb >> 16) & 0xff;
                int g = (rgb >> 8) & 0xff;
                int b = rgb & 0xff;
                if (r > 110 && r > g + 60 && b > g + 20) {
                    su += u + 0.5;
                    sv += v + 0.5;
                    n++;
                }
            }
        }
        return new double[] {su / Math.max(1, n), sv / Math.max(1, n), n};
    }

    @Test
    void theMicrophoneCarriesASoundOverLowNoise() throws Exception {
        start("");
        assertThat(DriverLink.await(LIMIT, () -> sink.on("audio").size() >= 3)).isTrue();
        AudioChunk quiet = (AudioChunk) sink.latest("audio");
        assertThat(quiet.format()).isEqualTo(new AudioFormat(16_000, 2, 16));
        assertThat(quiet.frameCount()).isEqualTo(512);
        assertThat(rms(quiet)).isLessThan(0.01).isGreaterThan(0);
        short[] tone = new short[16_000 / 4];
        for (int i = 0; i < tone.length; i++) {
            tone[i] = (short) (8_000 * Math.sin(2 * Math.PI * 523.25 * i / 16_000.0));
        }
        int before = sink.on("audio").size();
        mic.play(tone, time.nowMs() * 16);
        assertThat(DriverLink.await(LIMIT, () -> sink.on("audio").stream().skip(before)
                .anyMatch(a -> rms((AudioChunk) a) > 0.1))).isTrue();
    }

    /** Reads until the text read so far ends with {@code end} (the socket's read time-out bounds the wait). */
    static String readUntil(InputStream in, String end) throws IOException {
        StringBuilder b = new StringBuilder();
        while (!b.toString().endsWith(end) && b.length() < 100_000) {
            int c = in.read();
            if (c < 0) {
                break;
            }
            b.append((char) c);
        }
        return b.toString();
    }

    static double rms(AudioChunk chunk) {
        double[] left = chunk.channel(0);
        double s = 0;
        for (double v : left) {
            s += v * v;
        }
        return Math.sqrt(s / left.length);
    }

    @Test
    void theSpeakerRecordsWhatTheRobotSays() throws Exception {
        start("");
        assertThat(DriverLink.await(LIMIT, () -> {
            try {
                return links.get("speaker").write("speaker", AudioChunk.of(AudioFormat.MONO_16K, loud(8_000)));
            } catch (IOException e) {
                return false;
            }
        })).isTrue();
        assertThat(DriverLink.await(LIMIT, () -> said.summary().packets() >= 1)).isTrue();
        assertThat(said.summary().seconds()).isCloseTo(0.5, within(0.01));
        assertThat(said.summary().lastPeak()).isGreaterThan(0.4);
        assertThat(said.summary().rejected()).isZero();
    }

    private static byte[] loud(int samples) {
        byte[] pcm = new byte[samples * 2];
        for (int i = 0; i < samples; i++) {
            short v = (short) (16_000 * Math.sin(i * 0.3));
            pcm[2 * i] = (byte) v;
            pcm[2 * i + 1] = (byte) (v >> 8);
        }
        return pcm;
    }

    @Test
    void startingAServerAsksTheGuiToLoadItsViewerAsTekkotsuDoesByteForByte() throws Exception {
        servers = new TekkotsuServers(TekkotsuPorts.ANY_FREE, time, body, mic, said, at -> view());
        open.add(servers);
        TekkotsuPorts p = servers.ports();
        try (Socket s = new Socket("127.0.0.1", p.controller())) {
            s.setSoTimeout(5_000);
            s.getOutputStream().write(("!select \"Walk Remote Control\"\n!select \"Head Remote Control\"\n"
                    + "!select \"Raw Cam Server\"\n!select \"#Walk Remote Control\"\n!select \"#Raw Cam Server\"\n")
                    .getBytes(StandardCharsets.US_ASCII));
            String said = readUntil(s.getInputStream(), "close\nRawVisionGUI\n");

            // Controller::loadGUI: load, class, instance, port, then each argument quoted and followed by a space.
            assertThat(said).contains("load\norg.tekkotsu.mon.WalkGUI\nWalkGUI\n" + p.walk() + "\n\n")
                    .contains("load\norg.tekkotsu.mon.HeadPointGUI\nHeadPointGUI\n" + p.head() + "\n\n")
                    .contains("load\norg.tekkotsu.mon.VisionGUI\nRawVisionGUI\n" + p.rawCam() + "\n\"raw\" \""
                            + p.rawCam() + "\" \"tcp\" \n")
                    .contains("close\nWalkGUI\n")
                    .endsWith("close\nRawVisionGUI\n");
        }
    }

    @Test
    void garbageAndVanishingClientsLeaveTheRobotServing() throws Exception {
        start("");
        assertThat(DriverLink.await(LIMIT, () -> sink.on("ir").size() >= 2)).isTrue();
        // one client per server: the driver lets go of the controller and the e-stop first
        links.get("controller").close();
        links.get("estop").close();
        TekkotsuPorts p = servers.ports();
        for (int port : new int[] {p.controller(), p.eStop()}) {
            try (Socket s = new Socket("127.0.0.1", port)) {
                OutputStream out = s.getOutputStream();
                out.write(new byte[] {0, (byte) 0xff, '\n', 'x', '\r', '\n'});
                out.write("!select \"".getBytes(StandardCharsets.US_ASCII));
                out.write(new byte[10_000]);
                out.write("\n!bogus\n".getBytes(StandardCharsets.US_ASCII));
                out.flush();
            }
        }
        // a second speaker client is turned away while the driver holds the port (once it holds it: on a busy
        // machine the driver's speaker link may still be connecting, and the test's client would be the first)
        assertThat(DriverLink.await(LIMIT, () -> links.get("speaker").up())).isTrue();
        try (Socket s = new Socket("127.0.0.1", p.speaker())) {
            s.setSoTimeout((int) LIMIT.toMillis());
            assertThat(s.getInputStream().read()).isEqualTo(-1);
        }
        // a world-state client that connects and vanishes
        new Socket("127.0.0.1", p.worldState()).close();
        String reply = "";
        for (long end = System.nanoTime() + LIMIT.toNanos(); reply.isEmpty() && System.nanoTime() < end; ) {
            // one client at a time: the last hostile client may not have been let go yet
            try (Socket s = new Socket("127.0.0.1", p.controller())) {
                s.getOutputStream().write("!hello\n".getBytes(StandardCharsets.US_ASCII));
                s.setSoTimeout((int) LIMIT.toMillis());
                reply = readUntil(s.getInputStream(), "hello\n");
            } catch (IOException e) {
                reply = "";
            }
            Thread.sleep(reply.isEmpty() ? 50 : 0);
        }
        assertThat(reply).startsWith("refresh\nRoot Control\n8\n");
        int before = sink.on("ir").size();
        assertThat(DriverLink.await(LIMIT, () -> sink.on("ir").size() > before + 5)).isTrue();
        assertThat(links.get("walk").write("walk", VectorValue.of(0.1, 0, 0))).isTrue();
    }
}
