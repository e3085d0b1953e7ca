package org.habla.methods;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.net.SocketTimeoutException;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.junit.jupiter.api.Test;

/**
 * The Aibo-side methods inside the real daemon: real engine threads and real control sockets on
 * loopback. What a client writes goes down the layers through the methods and comes back up as what the
 * control architecture would read.
 */
class AiboSideDaemonTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    private static final String CONFIG = """
            {"system": "aibo-side-daemon-test", "status": {"port": %6$d}, "interfaces": [], "methods": [
              {"id": "blobsIn", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
               "params": {"kind": "record"}, "expose": {"port": %1$d, "name": "blobs"}},
              {"id": "where", "type": "coordinate-translation", "layer": "processing", "inputs": {"blobs": "blobsIn.out"},
               "params": {"hfovRad": 0.993, "vfovRad": 0.789, "cameraHeightM": 0.2}},
              {"id": "pos", "type": "pass-through", "layer": "virtual", "inputs": {"in": "where.position"},
               "params": {"kind": "record"}, "expose": {"port": %2$d, "name": "position"}},
              {"id": "buttonsIn", "type": "pass-through", "layer": "virtual", "inputs": {"in": "control"},
               "params": {"kind": "record"}, "expose": {"port": %3$d, "name": "touch"}},
              {"id": "down", "type": "pass-through", "layer": "processing", "inputs": {"in": "buttonsIn.out"},
               "params": {"kind": "record"}},
              {"id": "buttons", "type": "buttons", "layer": "sensors_actuators", "inputs": {"buttons": "down.out"}},
              {"id": "up", "type": "pass-through", "layer": "processing", "inputs": {"in": "buttons.touch"},
               "params": {"kind": "text", "delivery": "queue"}},
              {"id": "emotion", "type": "emotion-recognition", "layer": "virtual",
               "inputs": {"words": "control", "touch": "up.out"}, "expose": {"port": %4$d, "name": "emotion"}},
              {"id": "say", "type": "speech", "layer": "virtual", "inputs": {"text": "control", "emotion": "emotion.emotion"},
               "expose": {"port": %5$d, "name": "say"}},
              {"id": "voice", "type": "pass-through", "layer": "processing", "inputs": {"in": "say.audio"},
               "params": {"kind": "audio", "delivery": "queue"}},
              {"id": "speaker", "type": "speaker", "layer": "sensors_actuators", "inputs": {"audio": "voice.out"}}
            ]}
            """;

    /** A line client with reads that give up after 5 s. */
    private static final class Client implements AutoCloseable {
        private final Socket socket;
        private final BufferedReader in;
        private final OutputStream out;

        Client(int port) throws IOException {
            socket = new Socket("127.0.0.1", port);
            socket.setSoTimeout(5_000);
            in = new BufferedReader(new InputStreamReader(socket.getInputStream(), UTF_8));
            out = socket.getOutputStream();
            JsonNode hello = JSON.readTree(in.readLine());
            assertThat(hello.path("type").asText()).isEqualTo("hello");
        }

        void send(String line) throws IOException {
            out.write((line + "\n").getBytes(UTF_8));
            out.flush();
        }

        /** The value of the next sample line (at most 1000 lines are skipped); an error line fails. */
        JsonNode nextValue() throws IOException {
            JsonNode f = nextOf("sample", "error");
            if (f.path("type").asText().equals("error")) {
                throw new AssertionError("the daemon refused: " + f);
            }
            return f.path("value");
        }

        /** The next line of one of the {@code types} (at most 1000 lines are skipped). */
        JsonNode nextOf(String... types) throws IOException {
            for (int i = 0; i < 1000; i++) {
                String line;
                try {
                    line = in.readLine();
                } catch (SocketTimeoutException e) {
                    throw new AssertionError("no sample within 5 s", e);
                }
                if (line == null) {
                    throw new AssertionError("the daemon closed the socket");
                }
                JsonNode f = JSON.readTree(line);
                if (java.util.List.of(types).contains(f.path("type").asText())) {
                    return f;
                }
            }
            throw new AssertionError("no sample in 1000 lines");
        }

        @Override
        public void close() throws IOException {
            socket.close();
        }
    }

    @Test
    void wordsTouchesAndBlobsWrittenOnSocketsComeBackAsEmotionsAndPositions() throws Exception {
        PluginRegistry registry = PluginRegistry.discover();
        int[] ports = DaemonProcess.freePorts(6);
        HablaConfig config = new ConfigLoader(registry).parse(CONFIG.formatted(ports[0], ports[1], ports[2], ports[3], ports[4], ports[5]));
        try (Daemon daemon = Daemon.start(config, registry, EngineClock.system());
                Client emotion = new Client(daemon.port("emotion"));
                Client touch = new Client(daemon.port("touch"));
                Client blobs = new Client(daemon.port("blobs"));
                Client position = new Client(daemon.port("position"))) {
            emotion.send("{\"op\":\"write\",\"input\":\"words\",\"value\":\"good dog\"}");
            JsonNode praise = emotion.nextValue();
            assertThat(praise.path("emotion").asText()).isEqualTo("happy");
            assertThat(praise.path("words").asText()).isEqualTo("good dog");

            touch.send("{\"value\":{\"headTouch\":0.9,\"backMiddle\":0.0}}");
            JsonNode tap = emotion.nextValue();
            assertThat(tap.path("source").asText()).isEqualTo("touch");
            assertThat(tap.path("emotion").asText()).isEqualTo("angry");

            blobs.send("{\"value\":{\"width\":208,\"height\":160,\"blobs\":[{\"label\":\"pink\",\"cx\":60,\"cy\":100,"
                    + "\"area\":314,\"x\":50,\"y\":90,\"w\":20,\"h\":20}]}}");
            JsonNode seen = position.nextValue();
            assertThat(seen.path("seen").asBoolean()).isTrue();
            assertThat(seen.path("angleRad").asDouble()).as("a blob left of centre is to the left").isPositive();
            assertThat(seen.path("distanceM").asDouble()).as("a 20 px ball 192 px focal length away is about 0.95 m").isBetween(0.85, 1.05);
            blobs.send("{\"value\":{\"width\":208,\"height\":160,\"blobs\":[]}}");
            assertThat(position.nextValue().path("seen").asBoolean()).isFalse();

            emotion.send("{\"op\":\"write\",\"input\":\"words\",\"value\":17}");
            assertThat(emotion.nextOf("error").path("code").asText()).isEqualTo("bad_value");
            emotion.send("{\"op\":\"write\",\"input\":\"words\",\"value\":\"bad dog\"}");
            JsonNode scold = emotion.nextValue();
            assertThat(scold.path("emotion").asText()).as("a wrong value is refused, the next one still works")
                    .isIn("angry", "sad");
        }
    }
}
