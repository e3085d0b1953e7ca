package org.habla.status;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Socket;
import java.util.concurrent.atomic.AtomicInteger;
import org.habla.config.StatusConfig;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class StatusServerTest {

    /** Connects, reads everything the server sends, and returns its lines. */
    private static java.util.List<String> read(int port) throws IOException {
        try (Socket s = new Socket("127.0.0.1", port)) {
            s.setSoTimeout(5_000);
            return new BufferedReader(new InputStreamReader(s.getInputStream(), UTF_8)).lines().toList();
        }
    }

    @Test
    void eachClientGetsTheCurrentSnapshotAsOneLineThenTheConnectionCloses() throws Exception {
        AtomicInteger calls = new AtomicInteger();
        try (StatusServer server = new StatusServer(new StatusConfig("127.0.0.1", 7099), () -> {
            ObjectNode n = JsonNodeFactory.instance.objectNode().put("snapshot", calls.incrementAndGet());
            n.putObject("links").put("pioneer", "up");
            return n;
        })) {
            server.startOnAnyPort();
            assertThat(read(server.port())).containsExactly("{\"snapshot\":1,\"links\":{\"pioneer\":\"up\"}}");
            var second = read(server.port());
            assertThat(second).hasSize(1);
            assertThat(new ObjectMapper().readTree(second.get(0)).path("snapshot").asInt()).isEqualTo(2);
        }
    }

    @Test
    void aFailingSnapshotIsReportedAsAnErrorLineAndTheServerGoesOn() throws Exception {
        AtomicInteger calls = new AtomicInteger();
        try (StatusServer server = new StatusServer(StatusConfig.DEFAULTS, () -> {
            if (calls.incrementAndGet() == 1) {
                throw new IllegalStateException("engine busy");
            }
            return JsonNodeFactory.instance.objectNode().put("ok", true);
        })) {
            server.startOnAnyPort();
            assertThat(read(server.port()).get(0)).contains("\"code\":\"snapshot_failed\"", "engine busy");
            assertThat(read(server.port())).containsExactly("{\"ok\":true}");
        }
    }

    @Test
    void portZeroTurnsTheEndpointOff() throws Exception {
        try (StatusServer server = new StatusServer(new StatusConfig("127.0.0.1", 0),
                JsonNodeFactory.instance::objectNode)) {
            server.start();
            assertThat(server.running()).isFalse();
        }
    }
}
