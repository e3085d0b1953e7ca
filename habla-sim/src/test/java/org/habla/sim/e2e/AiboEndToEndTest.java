package org.habla.sim.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.sound.sampled.AudioSystem;
import javax.sound.sampled.AudioInputStream;
import org.habla.sim.scenario.TruthLink;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.Timeout;

/**
 * The Aibo set-up end to end: the simulated Aibo behind Tekkotsu's sockets, the daemon with
 * config/aibo.json (Sphinx-4 speech, OpenCV vision) in its own JVM, and a Python control client on
 * the contract's sockets. Real time (speed 1), since the spoken command's delay is part of the test.
 */
@Timeout(300)
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class AiboEndToEndTest {

    static SimulatedDeployment rig;

    @BeforeAll
    static void start() throws Exception {
        // Logs stay under target/ for a look after a failure.
        Path dir = Files.createDirectories(Path.of("target/e2e/aibo"));
        rig = new SimulatedDeployment("aibo", "aibo-arena", 1, dir, c -> { });
        rig.startSimulator();
        rig.startDaemon();
        rig.awaitReady(120_000);
    }

    @AfterAll
    static void stop() throws Exception {
        if (rig != null) {
            rig.close();
        }
    }

    @Test
    @Order(1)
    void theDistanceAndAngleSocketReportsTheBallWithinTwentyCentimetresAndTenDegrees() throws Exception {
        // The ball is at (1.9, 1.8) in a 2.5 m arena.
        double[][] poses = {{1.0, 1.2, 0.6}, {0.8, 0.5, 0.9}, {1.4, 1.7, 0.1}};
        for (double[] p : poses) {
            rig.place(p[0], p[1], p[2]);
            rig.after(3.0);   // the head finds the ball and the camera settles
            List<JsonNode> samples = rig.probe(30_000, "sample", "" + rig.port("distance_angle"), "5", "10");
            JsonNode truth = rig.truth.latest();
            assertThat(samples).hasSize(5);
            JsonNode v = samples.get(4).path("value");
            assertThat(v.path("seen").asBoolean()).as("ball seen from %s", (Object) p).isTrue();
            assertThat(Math.abs(v.path("distanceM").asDouble() - truth.path("distanceM").asDouble()))
                    .as("distance from (%s, %s): got %s, truth %s", p[0], p[1], v, truth.path("distanceM"))
                    .isLessThanOrEqualTo(0.2);
            assertThat(Math.abs(SimulatedDeployment.angleDiff(v.path("angleRad").asDouble(), truth.path("angleRad").asDouble())))
                    .as("angle from (%s, %s): got %s, truth %s", p[0], p[1], v, truth.path("angleRad"))
                    .isLessThanOrEqualTo(Math.toRadians(10));
        }
    }

    @Test
    @Order(2)
    void aSpokenCommandReachesTheCommandSocket() throws Exception {
        double longest = longestTake("go forward");
        // A teacher whose command went unheard says it again, as the paper's teacher did: up to three takes, each
        // a recording picked at random. Whatever reaches the socket must be the command said; a take that reaches
        // nothing is reported with what the daemon's chain says of it, so a miss is explained, not only counted.
        String heard = null;
        for (int take = 1; take <= 3 && heard == null; take++) {
            Process client = rig.probeAsync("first", "" + rig.port("command"), "20");
            try (BufferedReader out = new BufferedReader(new InputStreamReader(client.getInputStream(), StandardCharsets.UTF_8))) {
                assertThat(out.readLine()).contains("ready");
                long said = System.currentTimeMillis();
                rig.truth.send(TruthLink.op("say").put("label", "forward"));
                String line = out.readLine();
                if (line == null) {
                    System.out.printf("end to end: take %d of 'go forward' reached nothing in 20 s; the chain says:%n%s%n",
                            take, rig.methodStatus("microphone", "audio", "speech", "command"));
                    continue;
                }
                JsonNode got = new ObjectMapper().readTree(line);
                heard = got.path("value").asText();
                assertThat(heard).as("what take %d of 'go forward' gave", take).isEqualTo("forward");
                // How soon is a figure of bench/run worker (docs/performance.md), not of a test on a busy machine.
                System.out.printf("end to end: 'forward' on the command socket %.2f s after the teacher began take %d "
                        + "(each at most %.2f s)%n", got.path("wall").asDouble() - said / 1000.0, take, longest);
            } finally {
                client.waitFor(5, TimeUnit.SECONDS);
                client.destroyForcibly();
            }
        }
        assertThat(heard).as(() -> String.format("a phrase on the command socket from one of three takes; the daemon's "
                + "chain says:%n%s", rig.methodStatus("microphone", "audio", "speech", "command"))).isNotNull();
    }

    @Test
    @Order(3)
    void aTouchReachesTheRewardSocket() throws Exception {
        Process client = rig.probeAsync("first", "" + rig.port("reward"), "60");
        try (BufferedReader out = new BufferedReader(new InputStreamReader(client.getInputStream(), StandardCharsets.UTF_8))) {
            assertThat(out.readLine()).contains("ready");
            rig.truth.send(TruthLink.op("touch").put("sensor", "back"));
            assertThat(new ObjectMapper().readTree(out.readLine()).path("value").asDouble()).isEqualTo(1.0);
        } finally {
            client.destroyForcibly();
        }
        client = rig.probeAsync("first", "" + rig.port("reward"), "60");
        try (BufferedReader out = new BufferedReader(new InputStreamReader(client.getInputStream(), StandardCharsets.UTF_8))) {
            assertThat(out.readLine()).contains("ready");
            rig.truth.send(TruthLink.op("touch").put("sensor", "head"));
            assertThat(new ObjectMapper().readTree(out.readLine()).path("value").asDouble()).isEqualTo(-1.0);
        } finally {
            client.destroyForcibly();
        }
    }

    @Test
    @Order(4)
    void anActionMakesTheAiboWalkTheRightWay() throws Exception {
        JsonNode before = rig.place(0.8, 1.2, 0.0);
        rig.probe(20_000, "act", "" + rig.port("action"), "forward", "1.5");
        JsonNode after = rig.after(0.3);
        double dx = after.path("robot").path("xM").asDouble() - before.path("robot").path("xM").asDouble();
        assertThat(dx).as("walked forward along +x").isGreaterThan(0.05);

        before = rig.truth.latest();
        rig.probe(20_000, "act", "" + rig.port("action"), "left", "1.5");
        after = rig.after(0.3);
        double turned = SimulatedDeployment.angleDiff(after.path("robot").path("thetaRad").asDouble(),
                before.path("robot").path("thetaRad").asDouble());
        assertThat(turned).as("turned left (counter-clockwise)").isGreaterThan(0.2);
    }

    @Test
    @Order(5)
    void theDaemonSurvivesTheSimulatorRestartingAndReportsTheBallAgain() throws Exception {
        rig.killSimulator();
        assertThat(rig.daemon.alive()).isTrue();
        rig.startSimulator();
        rig.place(1.0, 1.2, 0.6);
        long end = System.nanoTime() + 60_000_000_000L;
        JsonNode v = null;
        while (System.nanoTime() < end) {
            List<JsonNode> s = rig.probe(30_000, "sample", "" + rig.port("distance_angle"), "3", "10");
            v = s.isEmpty() ? null : s.get(s.size() - 1);
            if (v != null && v.path("value").path("seen").asBoolean() && !v.path("stale").asBoolean()) {
                break;
            }
            Thread.sleep(500);
        }
        assertThat(v).isNotNull();
        assertThat(v.path("value").path("seen").asBoolean()).as("ball seen again after the restart").isTrue();
        assertThat(Math.abs(v.path("value").path("distanceM").asDouble() - rig.truth.latest().path("distanceM").asDouble()))
                .isLessThanOrEqualTo(0.2);
    }

    private static double longestTake(String phrase) throws Exception {
        Path utterances = SimulatedDeployment.HOME.resolve("habla-sim/src/main/resources/utterances");
        double longest = 0;
        for (String line : Files.readAllLines(utterances.resolve("index.txt"))) {
            String[] f = line.split("\t");
            if (f.length == 2 && f[1].equals(phrase)) {
                try (AudioInputStream in = AudioSystem.getAudioInputStream(utterances.resolve(f[0]).toFile())) {
                    longest = Math.max(longest, in.getFrameLength() / in.getFormat().getFrameRate());
                }
            }
        }
        assertThat(longest).isPositive();
        return longest;
    }
}
