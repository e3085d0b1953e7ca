package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.habla.sample.NumberValue;
import org.habla.security.AuditLog;
import org.habla.security.Credentials;
import org.habla.security.PortAccess;
import org.habla.security.PortSecurity;
import org.habla.security.Role;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** A control socket that requires authentication: who reads, who drives, who is refused, and the audit log. */
@Timeout(60)
class AuthenticatedSocketTest {

    private static final String DRIVER_TOKEN = "driver-token-0123456789";
    private static final String VIEWER_TOKEN = "viewer-token-0123456789";
    private static final Credentials CREDENTIALS = Credentials.of(Map.of(
            "mdb", Map.entry(DRIVER_TOKEN, Map.of("tracker", Role.COMMAND)),
            "viewer", Map.entry(VIEWER_TOKEN, Map.of("*", Role.READ))), null);
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    private final List<AutoCloseable> open = new ArrayList<>();
    private FakeControlPoint point;
    private ControlServer server;
    private Path auditFile;

    private void serve() throws IOException {
        point = FakeControlPoint.commanded(0);
        auditFile = dir.resolve("audit.log");
        AuditLog audit = AuditLog.open(auditFile);
        open.add(audit);
        server = new ControlServer(point, new Expose(point.name(), "127.0.0.1", 0), new Limits(4_096, 65_536, 4, 8),
                BlockBudget.of("test", 1 << 20),
                new PortSecurity(PortAccess.authenticated(point.name(), CREDENTIALS), audit, null));
        server.start();
        open.add(server);
    }

    private TestClient connect() throws IOException {
        TestClient c = new TestClient(server.port());
        open.add(c);
        Frame hello = c.next();
        assertThat(hello.type()).isEqualTo("hello");
        assertThat(hello.header().path("auth").asText()).isEqualTo("required");
        assertThat(hello.header().has("outputs")).as("an anonymous client learns nothing of the method").isFalse();
        return c;
    }

    private TestClient authenticated(String client, String token) throws IOException {
        TestClient c = connect();
        c.send("{\"op\":\"auth\",\"client\":\"" + client + "\",\"token\":\"" + token + "\"}");
        Frame hello = c.next("hello");
        assertThat(hello.header().path("client").asText()).isEqualTo(client);
        assertThat(hello.header().has("outputs")).isTrue();
        return c;
    }

    @AfterEach
    void closeAll() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
    }

    @Test
    void withoutCredentialsAClientReadsNothingAndDrivesNothing() throws Exception {
        serve();
        TestClient c = connect();
        point.emit("distance", new NumberValue(3));
        c.send("{\"input\":\"action\",\"value\":\"forward\",\"id\":1}");
        List<String> types = new ArrayList<>();
        for (Frame f = c.next(); f != null; f = c.next()) {
            types.add(f.type());
            assertThat(f.header().path("code").asText()).isEqualTo("auth_required");
        }
        assertThat(types).containsExactly("error");
        assertThat(point.writes).isEmpty();
        assertThat(audit()).anySatisfy(e -> assertThat(e.toString())
                .contains("\"client\":\"anonymous\"", "\"action\":\"write\"", "\"accepted\":false", "auth_required"));
    }

    @Test
    void nothingOvertakesTheHelloThatAnswersTheAuthLine() throws Exception {
        serve();
        java.util.concurrent.atomic.AtomicBoolean streaming = new java.util.concurrent.atomic.AtomicBoolean(true);
        Thread emitter = Thread.ofPlatform().daemon().start(() -> {
            for (int i = 0; streaming.get(); i++) {
                point.emit("distance", new NumberValue(i));
                if (i % 50 == 0) {
                    point.stale(i % 100 == 0, "a link comes and goes"); // a stale line to every client
                }
            }
        });
        try {
            for (int n = 0; n < AUTH_ROUNDS; n++) {
                try (TestClient c = connect()) {
                    c.send("{\"op\":\"auth\",\"client\":\"viewer\",\"token\":\"" + VIEWER_TOKEN + "\"}");
                    Frame first = c.next();
                    assertThat(first.type()).as("round %d: the first line after the auth line", n).isEqualTo("hello");
                    assertThat(first.header().path("client").asText()).isEqualTo("viewer");
                }
            }
        } finally {
            streaming.set(false);
            emitter.join(5_000);
        }
    }

    /** Authentications raced against a stream of samples and stale lines. */
    private static final int AUTH_ROUNDS = 300;

    @Test
    void aReadClientReadsButCannotWrite() throws Exception {
        serve();
        TestClient viewer = authenticated("viewer", VIEWER_TOKEN);
        point.emit("distance", new NumberValue(3));
        assertThat(viewer.next("sample").header().path("value").asDouble()).isEqualTo(3.0);
        viewer.send("{\"input\":\"action\",\"value\":\"forward\",\"id\":1}");
        Frame refused = viewer.next("error");
        assertThat(refused.header().path("code").asText()).isEqualTo("forbidden");
        assertThat(point.writes).isEmpty();
        viewer.send("{\"op\":\"ping\",\"id\":2}");
        assertThat(viewer.next("pong")).as("a refused write leaves the reader connected").isNotNull();
        assertThat(audit()).anySatisfy(e -> assertThat(e.toString())
                .contains("\"client\":\"viewer\"", "\"accepted\":false", "forbidden"));
    }

    @Test
    void aCommandClientDrivesAndIsNamedAsTheCommander() throws Exception {
        serve();
        TestClient mdb = authenticated("mdb", DRIVER_TOKEN);
        mdb.send("{\"input\":\"action\",\"value\":\"forward\",\"id\":1}");
        assertThat(mdb.next("ok")).isNotNull();
        assertThat(point.writes.poll(5, TimeUnit.SECONDS)).isNotNull();
        assertThat(server.stats().path("control").path("holder").path("client").asText()).isEqualTo("mdb");
        assertThat(audit()).anySatisfy(e -> assertThat(e.toString()).contains("\"client\":\"mdb\"",
                "\"input\":\"action\"", "\"value\":\"forward\"", "\"accepted\":true"));
    }

    @Test
    void aWrongSecretIsRefusedAfterADelayCountedAndAudited() throws Exception {
        serve();
        TestClient c = connect();
        long start = System.nanoTime();
        c.send("{\"op\":\"auth\",\"client\":\"mdb\",\"token\":\"not-the-token-at-all\"}");
        Frame refused = c.next("error");
        long tookMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        assertThat(refused.header().path("code").asText()).isEqualTo("auth_failed");
        assertThat(refused.header().path("message").asText()).doesNotContain("not-the-token-at-all");
        assertThat(tookMs).isGreaterThanOrEqualTo(PortAccess.FAILURE_DELAY_MS);
        assertThat(c.next()).as("the connection is closed").isNull();
        assertThat(server.stats().path("authFailures").asLong()).isEqualTo(1);
        assertThat(audit()).anySatisfy(e -> assertThat(e.toString()).contains("\"client\":\"mdb\"",
                "\"action\":\"auth\"", "\"accepted\":false", "auth_failed"));
        assertThat(Files.readString(auditFile)).doesNotContain("not-the-token-at-all", DRIVER_TOKEN);
    }

    private List<JsonNode> audit() throws Exception {
        await("the audit log has an entry", () -> {
            try {
                return Files.size(auditFile) > 0;
            } catch (IOException e) {
                return false;
            }
        });
        List<JsonNode> entries = new ArrayList<>();
        for (String line : Files.readAllLines(auditFile)) {
            entries.add(JSON.readTree(line));
        }
        return entries;
    }

    private static void await(String what, BooleanSupplier condition) throws InterruptedException {
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > until) {
                throw new AssertionError("timed out waiting until " + what);
            }
            Thread.sleep(5);
        }
    }
}
