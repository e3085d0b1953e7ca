package org.habla.sim.pioneer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.BufferedReader;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import org.habla.sample.RecordValue;
import org.habla.sample.VectorValue;
import org.habla.sim.world.TruthClient;
import org.habla.sim.world.World;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The teacher's notes on the microphone stream and rewards on the keyboard, read from their sockets. */
class TeacherSoundsTest {

    private static final int RATE = 16_000;
    private PioneerSim sim;

    @AfterEach
    void stop() {
        if (sim != null) {
            sim.close();
        }
    }

    @Test
    void aNoteOperationPlaysTheLabelsNoteOnTheMicrophoneAndTheJudgementIsTyped() throws Exception {
        sim = PioneerSim.start(PioneerSimOptions.forTest(World.builtIn("pioneer-room"), 5));
        try (Socket mic = new Socket(InetAddress.getLoopbackAddress(), sim.micPort());
             Socket keys = new Socket(InetAddress.getLoopbackAddress(), sim.keysPort());
             TruthClient truth = new TruthClient(sim.truthPort())) {
            mic.setSoTimeout(5_000);
            keys.setSoTimeout(5_000);
            DataInputStream pcm = new DataInputStream(mic.getInputStream());
            BufferedReader typed = new BufferedReader(new InputStreamReader(keys.getInputStream(), StandardCharsets.UTF_8));
            short[] quiet = read(pcm, RATE / 2);
            assertThat(rms(quiet, 0, quiet.length)).as("background noise").isBetween(0.001, 0.01);
            assertThat(truth.op("{\"op\":\"note\",\"label\":\"left\"}").has("ok")).isTrue();
            // Find the tone within the next 3 s of audio.
            short[] audio = read(pcm, 3 * RATE);
            int start = -1;
            for (int i = 0; i + 160 <= audio.length; i += 160) {
                if (rms(audio, i, 160) > 0.1) {
                    start = i;
                    break;
                }
            }
            assertThat(start).as("a loud stretch after the note op").isNotNegative();
            int from = start + RATE / 20;
            int length = RATE / 4; // 0.25 s inside the 0.4 s tone
            assertThat(rms(audio, from, length)).isCloseTo(0.3 / Math.sqrt(2), within(0.01));
            assertThat(zeroCrossingHz(audio, from, length)).isCloseTo(659.25, within(4.0));
            int toneEnd = start;
            while (toneEnd + 160 <= audio.length && rms(audio, toneEnd, 160) > 0.05) {
                toneEnd += 160;
            }
            assertThat((toneEnd - start) / (double) RATE).isCloseTo(0.4, within(0.02));
            // The robot did not turn left: 1.5 s later the teacher types pain.
            assertThat(typed.readLine()).isEqualTo("-1");
            assertThat(truth.op("{\"op\":\"reward\",\"value\":1}").has("ok")).isTrue();
            assertThat(typed.readLine()).isEqualTo("+1");
        }
    }

    @Test
    void thePresentTeacherCommandsTowardsTheTargetAndRewardsARobotThatObeys() throws Exception {
        World room = World.builtIn("pioneer-room");
        sim = PioneerSim.start(PioneerSimOptions.forTest(room, 10));
        try (Socket keys = new Socket(InetAddress.getLoopbackAddress(), sim.keysPort());
             TruthClient truth = new TruthClient(sim.truthPort())) {
            keys.setSoTimeout(10_000);
            BufferedReader typed = new BufferedReader(new InputStreamReader(keys.getInputStream(), StandardCharsets.UTF_8));
            // Facing away from the target (bearing ≈ 2.5 rad to the left), the robot turns left slowly before the
            // teacher comes in: 3 s later the target is still far to the left, so the teacher says "left", and the
            // robot, still turning left, has obeyed when judged 1.5 s after — whatever the test's own latency.
            assertThat(truth.op("{\"op\":\"reset\",\"robot\":{\"xM\":1.5,\"yM\":1.5,\"thetaRad\":-1.8}}").has("ok")).isTrue();
            try (DriverHarness robot = new DriverHarness(sim.arcosPort(), 50)) {
                robot.command("motion", VectorValue.of(0, 0.3));
                robot.await("odometry", RecordValue.class, o -> o.number("wRadps") > 0.29, 10_000);
                double arrived = sim.clock().nowS();
                assertThat(truth.op("{\"op\":\"teacher\",\"present\":true}").has("ok")).isTrue();
                assertThat(typed.readLine()).isEqualTo("+1");
                var judged = truth.next(n -> n.has("t") && !n.at("/teacher/lastReward").isNull(), 1_000);
                assertThat(judged.at("/teacher/lastCommand").textValue()).isEqualTo("left");
                assertThat(judged.get("t").doubleValue() - arrived).isBetween(4.5, 6.0);
                robot.command("motion", VectorValue.of(0, 0));
            }
        }
    }

    private static short[] read(DataInputStream in, int samples) throws IOException {
        byte[] bytes = new byte[2 * samples];
        in.readFully(bytes);
        short[] out = new short[samples];
        for (int i = 0; i < samples; i++) {
            out[i] = (short) ((bytes[2 * i] & 0xFF) | (bytes[2 * i + 1] << 8));
        }
        return out;
    }

    private static double rms(short[] s, int from, int length) {
        double sum = 0;
        for (int i = from; i < from + length; i++) {
            double v = s[i] / 32768.0;
            sum += v * v;
        }
        return Math.sqrt(sum / length);
    }

    /** Frequency from sign changes between samples well away from zero (so noise near zero is not counted). */
    private static double zeroCrossingHz(short[] s, int from, int length) {
        int crossings = 0;
        int sign = 0;
        int first = -1;
        int last = -1;
        for (int i = from; i < from + length; i++) {
            int now = s[i] > 1000 ? 1 : s[i] < -1000 ? -1 : 0;
            if (now != 0 && sign != 0 && now != sign) {
                crossings++;
                if (first < 0) {
                    first = i;
                }
                last = i;
            }
            if (now != 0) {
                sign = now;
            }
        }
        return (crossings - 1) / 2.0 / ((last - first) / (double) RATE);
    }
}
