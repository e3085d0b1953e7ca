package org.habla.methods.virtual;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;

/** The action socket as a control architecture sees it: a real daemon, a real loopback connection. */
class ActionSocketTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    private static final String CONFIG = """
            {"system": "action-socket-test", "interfaces": [], "status": {"port": 0},
             "methods": [{"id": "action", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
                          "params": {"durationMs": 200}, "expose": {"port": %d, "name": "action"}}]}
            """;

    @Test
    void aRefusedLabelComesBackAsAnErrorLineAndAGoodOneIsEchoed() throws Exception {
        HablaConfig config = new ConfigLoader(PluginRegistry.discover()).parse(CONFIG.formatted(freePort()));
        try (Daemon daemon = Daemon.start(config, PluginRegistry.discover(), EngineClock.system());
                Socket socket = new Socket("127.0.0.1", daemon.port("action"))) {
            socket.setSoTimeout(5_000);
            BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(), UTF_8));
            OutputStream out = socket.getOutputStream();
            assertThat(JSON.readTree(in.readLine()).path("type").asText()).isEqualTo("hello");

            out.write("{\"value\": \"jump\", \"id\": 1}\n".getBytes(UTF_8));
            JsonNode error = next(in, "error");
            assertThat(error.path("code").asText()).isEqualTo("bad_value");
            assertThat(error.path("message").asText()).contains("unknown action 'jump'", "forward, left");
            assertThat(error.path("id").asInt()).isEqualTo(1);

            out.write("{\"value\": \"left\", \"id\": 2}\n".getBytes(UTF_8));
            JsonNode echo = null;
            for (int i = 0; i < 20 && echo == null; i++) {
                JsonNode line = next(in, "sample");
                if (line.path("output").asText().equals("action")) {
                    echo = line;
                }
            }
            assertThat(echo).as("the accepted label is echoed on output action").isNotNull();
            assertThat(echo.path("value").asText()).isEqualTo("left");
        }
    }

    private static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    /** The next line of {@code type}, skipping others (at most 50). */
    private static JsonNode next(BufferedReader in, String type) throws Exception {
        for (int i = 0; i < 50; i++) {
            String line = in.readLine();
            assertThat(line).as("the server closed before a '" + type + "' line").isNotNull();
            JsonNode node = JSON.readTree(line);
            if (node.path("type").asText().equals(type)) {
                return node;
            }
        }
        throw new AssertionError("no '" + type + "' line in 50");
    }
}
