package org.habla.sim.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

class TruthServerTest {

    private final World room = World.builtIn("pioneer-room");
    private final List<String> heard = new ArrayList<>();
    private SimClock clock;
    private Scene scene;
    private TruthServer server;

    @BeforeEach
    void start() throws IOException {
        TeacherVoice voice = new TeacherVoice() {
            @Override
            public synchronized double giveCommand(String label) {
                heard.add(label);
                return 0;
            }

            @Override
            public synchronized void giveReward(double value) {
                heard.add(String.valueOf(value));
            }
        };
        scene = new Scene(room, new Body(new Body.Limits(0.25, 0.5, 2, 0.5, 2), room.robotStart()),
                new Teacher(room.teacher().withPresent(false), voice));
        clock = new SimClock(10, 0.01);
        clock.add(scene);
        server = new TruthServer(scene, 0);
        clock.add(server);
        clock.start();
    }

    @AfterEach
    void stop() {
        clock.close();
        server.close();
    }

    @Test
    void linesTellWhereTheRobotAndTheTargetAreTenTimesASimSecond() throws IOException {
        try (TruthClient client = new TruthClient(server.port())) {
            JsonNode a = client.truth();
            JsonNode b = client.truth();
            assertThat(b.get("t").doubleValue() - a.get("t").doubleValue()).isCloseTo(0.1, within(0.011));
            assertThat(b.at("/robot/xM").doubleValue()).isEqualTo(3.0);
            assertThat(b.at("/target/radiusM").doubleValue()).isEqualTo(0.15);
            double centre = Math.hypot(4.5 - 3.0, 4.0 - 3.0);
            assertThat(b.get("distanceM").doubleValue()).isCloseTo(centre - 0.15 - 0.25, within(1e-3));
            assertThat(b.get("angleRad").doubleValue()).isCloseTo(Math.atan2(1.0, 1.5), within(1e-3));
            assertThat(b.get("stalled").booleanValue()).isFalse();
            assertThat(b.at("/teacher/present").booleanValue()).isFalse();
            assertThat(b.at("/teacher/lastCommand").isNull()).isTrue();
            assertThat(b.get("episode").intValue()).isZero();
        }
    }

    @Test
    void resetMovesTheRobotAndTheTargetAndStartsANewEpisode() throws IOException {
        try (TruthClient client = new TruthClient(server.port())) {
            JsonNode reply = client.op("{\"op\":\"reset\",\"robot\":{\"xM\":3,\"yM\":2,\"thetaRad\":1.0},"
                    + "\"target\":{\"xM\":3,\"yM\":5}}");
            assertThat(reply.get("ok").booleanValue()).isTrue();
            JsonNode t = client.next(n -> n.has("t") && n.get("episode").intValue() == 1, 50);
            assertThat(t.at("/robot/xM").doubleValue()).isEqualTo(3.0);
            assertThat(t.at("/robot/thetaRad").doubleValue()).isEqualTo(1.0);
            assertThat(t.at("/target/yM").doubleValue()).isEqualTo(5.0);
            assertThat(t.get("distanceM").doubleValue()).isCloseTo(3 - 0.15 - 0.25, within(1e-3));
            assertThat(t.get("angleRad").doubleValue()).isCloseTo(Math.PI / 2 - 1.0, within(1e-3));
            JsonNode bad = client.op("{\"op\":\"reset\",\"robot\":{\"xM\":0.1,\"yM\":2}}");
            assertThat(bad.get("error").textValue()).contains("overlap");
        }
    }

    @Test
    void theTeacherCanBeMadeToSpeakRewardAndComeAndGo() throws IOException {
        try (TruthClient client = new TruthClient(server.port())) {
            assertThat(client.op("{\"op\":\"note\",\"label\":\"left\"}").has("ok")).isTrue();
            JsonNode t = client.next(n -> n.has("t") && "left".equals(n.at("/teacher/lastCommand").textValue()), 50);
            assertThat(t.at("/teacher/lastCommand").textValue()).isEqualTo("left");
            // The robot did not turn: the judgement 1.5 s later is pain.
            JsonNode judged = client.next(n -> n.has("t") && !n.at("/teacher/lastReward").isNull(), 40);
            assertThat(judged.at("/teacher/lastReward").doubleValue()).isEqualTo(-1.0);
            assertThat(client.op("{\"op\":\"reward\",\"value\":1}").has("ok")).isTrue();
            assertThat(client.op("{\"op\":\"teacher\",\"present\":true}").has("ok")).isTrue();
            assertThat(client.next(n -> n.has("t") && n.at("/teacher/present").booleanValue(), 50)).isNotNull();
            synchronized (heard) {
                assertThat(heard).startsWith("left", "-1.0", "1.0");
            }
        }
    }

    @Test
    void badOperationsGetAnErrorAndTheConnectionKeepsWorking() throws IOException {
        try (TruthClient client = new TruthClient(server.port())) {
            assertThat(client.op("this is not json").get("error").textValue()).contains("not a JSON object");
            assertThat(client.op("[1,2]").get("error").textValue()).contains("\"op\"");
            assertThat(client.op("{\"op\":\"fly\"}").get("error").textValue()).contains("unknown op 'fly'");
            assertThat(client.op("{\"op\":\"say\",\"label\":\"jump\"}").get("error").textValue()).contains("jump");
            assertThat(client.op("{\"op\":\"reward\",\"value\":7}").get("error").textValue()).contains("[-1, 1]");
            assertThat(client.op("{\"op\":\"reward\"}").get("error").textValue()).contains("value");
            assertThat(client.op("{\"op\":\"touch\",\"sensor\":\"head\"}").get("error").textValue()).contains("touch");
            assertThat(client.op("{\"op\":\"reset\",\"robot\":{\"xM\":\"far\"}}").get("error").textValue()).contains("xM");
            assertThat(client.op("x".repeat(LineServer.MAX_LINE_BYTES + 10)).get("error").textValue())
                    .contains("maxLineBytes");
            assertThat(client.op("{\"op\":\"teacher\",\"present\":false}").get("ok").booleanValue()).isTrue();
            assertThat(client.truth().has("robot")).isTrue();
        }
    }

    @Test
    void aClientThatVanishesMidLineDoesNotDisturbOthers() throws IOException {
        try (Socket rude = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
            OutputStream out = rude.getOutputStream();
            out.write("{\"op\":\"res".getBytes(StandardCharsets.UTF_8));
            out.flush();
        }
        try (TruthClient client = new TruthClient(server.port())) {
            assertThat(client.truth().has("t")).isTrue();
            assertThat(client.op("{\"op\":\"teacher\",\"present\":false}").get("ok").booleanValue()).isTrue();
        }
    }
}
