package org.habla.status;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.Socket;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.habla.net.Limits;
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

    /** A snapshot far larger than what the kernel buffers for a client that does not read. */
    private static ObjectNode hugeSnapshot() {
        return JsonNodeFactory.instance.objectNode().put("pad", "x".repeat(8 << 20));
    }

    @Test
    void aClientThatNeverTakesItsAnswerIsDisconnectedAtTheFrameDeadline() throws Exception {
        Limits limits = Limits.DEFAULTS.withDeadlines(60_000, 300, 10_000);
        try (StatusServer server = new StatusServer(new StatusConfig("127.0.0.1", 7099), limits,
                StatusServerTest::hugeSnapshot);
                Socket s = new Socket("127.0.0.1", startOnAnyPort(server))) {
            OutputStream out = s.getOutputStream();
            // The client never reads. Each byte it writes lands unread on the server, so that the server's
            // close resets the connection and the next write fails: that is how the client sees it closed.
            boolean closed = false;
            long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (!closed && System.nanoTime() < until) {
                try {
                    out.write('x');
                    out.flush();
                    Thread.sleep(20);
                } catch (IOException e) {
                    closed = true;
                }
            }
            assertThat(closed).as("the server gave up on a client that does not read").isTrue();
            assertThat(server.answering()).isZero();
        }
    }

    @Test
    void clientsThatDoNotReadCannotHoldTheEndpoint() throws Exception {
        Limits limits = Limits.DEFAULTS.withCaps(16, 4).withDeadlines(60_000, 60_000, 10_000);
        AtomicInteger calls = new AtomicInteger();
        try (StatusServer server = new StatusServer(new StatusConfig("127.0.0.1", 7099), limits, () -> {
            calls.incrementAndGet();
            return hugeSnapshot();
        })) {
            int port = startOnAnyPort(server);
            java.util.List<Socket> crowd = new java.util.ArrayList<>();
            try {
                for (int i = 0; i < 8; i++) {
                    crowd.add(new Socket("127.0.0.1", port));
                }
                long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                while (calls.get() < 8 && System.nanoTime() < until) {
                    Thread.sleep(5);
                }
                assertThat(server.answering()).as("answers in flight").isLessThanOrEqualTo(4);
                var lines = read(port);
                assertThat(lines).hasSize(1);
                assertThat(lines.get(0)).hasSize((8 << 20) + "{\"pad\":\"\"}".length());
            } finally {
                for (Socket s : crowd) {
                    s.close();
                }
            }
        }
    }

    private static int startOnAnyPort(StatusServer server) throws IOException {
        server.startOnAnyPort();
        return server.port();
    }

    @Test
    void portZeroTurnsTheEndpointOff() throws Exception {
        try (StatusServer server = new StatusServer(new StatusConfig("127.0.0.1", 0),
                JsonNodeFactory.instance::objectNode)) {
            server.start();
            assertThat(server.running()).isFalse();
        }
    }

    @Test
    void withAuthenticationOnlyAClientWithTheReadRoleGetsTheSnapshot() throws Exception {
        var credentials = org.habla.security.Credentials.of(java.util.Map.of(
                "viewer", java.util.Map.entry("viewer-token-0123456789", java.util.Map.of("@status",
                        org.habla.security.Role.READ)),
                "driver", java.util.Map.entry("driver-token-0123456789", java.util.Map.of("action",
                        org.habla.security.Role.COMMAND))), null);
        try (StatusServer server = new StatusServer(new StatusConfig("127.0.0.1", 7099), Limits.DEFAULTS,
                () -> JsonNodeFactory.instance.objectNode().put("snapshot", 1),
                org.habla.security.PortAccess.authenticated("@status", credentials))) {
            server.startOnAnyPort();
            assertThat(exchange(server.port(), "{\"op\":\"ping\"}")).hasSize(2)
                    .last().asString().contains("auth_required").doesNotContain("snapshot");
            assertThat(exchange(server.port(), "{\"op\":\"auth\",\"client\":\"viewer\",\"token\":\"wrong-wrong-wrong-wrong\"}"))
                    .last().asString().contains("auth_failed").doesNotContain("snapshot");
            assertThat(exchange(server.port(), "{\"op\":\"auth\",\"client\":\"driver\",\"token\":\"driver-token-0123456789\"}"))
                    .last().asString().contains("forbidden");
            assertThat(exchange(server.port(), "{\"op\":\"auth\",\"client\":\"viewer\",\"token\":\"viewer-token-0123456789\"}"))
                    .containsExactly("{\"type\":\"hello\",\"protocol\":\"habla-status/1\",\"auth\":\"required\"}",
                            "{\"snapshot\":1}");
            assertThat(server.access().failures()).isEqualTo(2);
        }
    }

    @Test
    void everyRefusedLoginIsCountedAndAuditedAndAnAddressOutOfTriesIsNotChecked() throws Exception {
        var credentials = org.habla.security.Credentials.of(java.util.Map.of("viewer", java.util.Map.entry(
                "viewer-token-0123456789", java.util.Map.of("@status", org.habla.security.Role.READ))), null);
        java.util.List<org.habla.security.AuditEntry> audited = new java.util.concurrent.CopyOnWriteArrayList<>();
        org.habla.security.AuditLog audit = org.habla.security.AuditLog.withoutFile();
        audit.addListener(audited::add);
        try (StatusServer server = new StatusServer(new StatusConfig("127.0.0.1", 7099), Limits.DEFAULTS,
                () -> JsonNodeFactory.instance.objectNode().put("snapshot", 1), new org.habla.security.PortSecurity(
                        org.habla.security.PortAccess.authenticated("@status", credentials), audit, null))) {
            server.startOnAnyPort();
            int attempts = org.habla.security.LoginThrottle.BURST + 5;
            java.util.List<String> answers = new java.util.concurrent.CopyOnWriteArrayList<>();
            try (var guessers = java.util.concurrent.Executors.newVirtualThreadPerTaskExecutor()) {
                for (int i = 0; i < attempts; i++) { // at once: more than the address's burst of tries
                    String guess = "{\"op\":\"auth\",\"client\":\"viewer\",\"token\":\"guess-" + i + "-0123456789\"}";
                    guessers.submit(() -> answers.add(exchange(server.port(), guess).getLast()));
                }
            }
            assertThat(answers).filteredOn(a -> a.contains("auth_failed")).hasSizeGreaterThanOrEqualTo(1)
                    .hasSizeLessThanOrEqualTo(org.habla.security.LoginThrottle.BURST + 1);
            assertThat(answers).filteredOn(a -> a.contains("auth_throttled")).isNotEmpty();
            assertThat(server.access().failures()).isEqualTo(attempts);
            assertThat(audited).hasSize(attempts).allSatisfy(e -> assertThat(e.json().toString()).contains(
                    "\"socket\":\"@status\"", "\"action\":\"auth\"", "\"accepted\":false",
                    "\"address\":\"127.0.0.1:"));
        }
    }

    /** Connects, sends one line, and returns every line the server sends before it closes. */
    private static java.util.List<String> exchange(int port, String line) throws IOException {
        try (Socket s = new Socket("127.0.0.1", port)) {
            s.setSoTimeout(5_000);
            s.getOutputStream().write((line + "\n").getBytes(UTF_8));
            return new BufferedReader(new InputStreamReader(s.getInputStream(), UTF_8)).lines().toList();
        }
    }
}
