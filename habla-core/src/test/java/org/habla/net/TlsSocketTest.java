package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.habla.security.AuditLog;
import org.habla.security.Credentials;
import org.habla.security.PortAccess;
import org.habla.security.PortSecurity;
import org.habla.security.Role;
import org.habla.security.Tls;
import org.habla.testing.LabCertificate;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A control socket that speaks TLS with a lab certificate made by {@code openssl} as docs/security.md says: the
 * example Python client, with Python's own {@code ssl}, authenticates and reads {@code distance_angle}; a plain
 * client gets a plain {@code tls_required} line and the connection closes, instead of waiting for a hello.
 */
@Timeout(120)
class TlsSocketTest {

    private static final Path CLIENT = Paths.get("..", "clients", "python", "src").toAbsolutePath().normalize();
    private static final String TOKEN = "mdb-token-0123456789abcdef";

    @TempDir
    static Path dir;
    private static Path certificate;
    private static Path key;

    private final List<AutoCloseable> open = new ArrayList<>();

    @BeforeAll
    static void makeALabCertificate() throws Exception {
        LabCertificate lab = LabCertificate.make(dir, "lab");
        certificate = lab.certificate();
        key = lab.key();
    }

    @AfterEach
    void closeAll() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
    }

    private ControlServer serve(FakeControlPoint point) throws IOException {
        Credentials credentials = Credentials.of(Map.of("mdb", Map.entry(TOKEN, Map.of("*", Role.READ))), null);
        ControlServer server = new ControlServer(point, new Expose(point.name(), "127.0.0.1", 0, true),
                new Limits(4_096, 65_536, 4, 8), BlockBudget.of("test", 1 << 20),
                new PortSecurity(PortAccess.authenticated(point.name(), credentials), AuditLog.withoutFile(),
                        Tls.server(certificate, key)));
        server.start();
        open.add(server);
        return server;
    }

    @Test
    void aPythonClientWithSslReadsDistanceAngleFromATlsSocket() throws Exception {
        FakeControlPoint point = new FakeControlPoint("distance_angle", false, false);
        ControlServer server = serve(point);
        point.emit("distance", new org.habla.sample.NumberValue(1.25));
        String script = """
                import json, sys
                import habla
                with habla.connect("127.0.0.1", int(sys.argv[1]), client="mdb", token=sys.argv[2], tls=sys.argv[3]) as s:
                    print(s._sock.version(), s.hello.socket, s.hello.client)
                    s.send({"op": "latest"})
                    print(json.dumps(s.next_sample(timeout=10).line))
                """;
        ProcessBuilder pb = new ProcessBuilder("python3", "-c", script, "" + server.port(), TOKEN,
                certificate.toString()).directory(CLIENT.toFile()).redirectErrorStream(true);
        pb.environment().put("PYTHONDONTWRITEBYTECODE", "1");
        Process p = pb.start();
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as("python: %s", out).isZero();
        assertThat(out).startsWith("TLSv1.3 distance_angle mdb").contains("\"output\": \"distance\"", "1.25");
    }

    @Test
    void aPlainClientOnATlsSocketGetsAClearErrorNotAHang() throws Exception {
        ControlServer server = serve(new FakeControlPoint("distance_angle", false, false));
        try (TestClient waiting = new TestClient(server.port())) {
            Frame f = waiting.next();
            assertThat(f.header().path("code").asText()).isEqualTo("tls_required");
            assertThat(f.header().path("message").asText()).contains("openssl s_client");
            assertThat(waiting.next()).as("then the connection closes").isNull();
        }
        try (TestClient talking = new TestClient(server.port())) {
            talking.send("{\"op\":\"ping\"}");
            assertThat(talking.next().header().path("code").asText()).isEqualTo("tls_required");
        }
        // The server counts a refusal once it has told the client and closed: the count may come a moment after.
        long until = System.nanoTime() + 10_000_000_000L;
        while (server.stats().path("plainClientsRefused").asLong() < 2 && System.nanoTime() < until) {
            Thread.sleep(5);
        }
        assertThat(server.stats().path("plainClientsRefused").asLong()).isEqualTo(2);
    }
}
