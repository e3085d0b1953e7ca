package org.habla.drivers.mqtt;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.habla.config.ConfigLoader;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.habla.testing.Mosquitto;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code mqtt} driver logging in to a Mosquitto broker that takes TLS only (a certificate signed by a test
 * authority made with openssl) and a user name and password ({@code mosquitto_passwd}).
 */
@Timeout(60)
class MqttLoginTest {

    private static final PluginRegistry REGISTRY = PluginRegistry.discover();

    @TempDir
    static Path certs;

    @BeforeAll
    static void makeCertificatesAndPasswords() throws Exception {
        run("openssl", "req", "-x509", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes", "-keyout", "ca.key", "-out", "ca.pem",
                "-days", "2", "-subj", "/CN=habla-test-ca");
        run("openssl", "req", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes", "-keyout", "server.key", "-out", "server.csr",
                "-subj", "/CN=localhost");
        Files.writeString(certs.resolve("san.ext"), "subjectAltName=IP:127.0.0.1,DNS:localhost\n");
        run("openssl", "x509", "-req", "-in", "server.csr", "-CA", "ca.pem", "-CAkey", "ca.key", "-CAcreateserial",
                "-out", "server.pem", "-days", "2", "-extfile", "san.ext");
        run("mosquitto_passwd", "-b", "-c", "passwd", "habla", "s3cret");
        Files.writeString(certs.resolve("password"), "s3cret\n");
        Files.writeString(certs.resolve("wrong-password"), "guess\n");
        // Mosquitto started as root reads its files as the user 'mosquitto': let it (test certificates only).
        run("chmod", "-R", "a+rX", certs.toString());
    }

    private static void run(String... cmd) throws Exception {
        Process p = new ProcessBuilder(cmd).directory(certs.toFile()).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes());
        assertThat(p.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(String.join(" ", cmd) + ": " + out).isZero();
    }

    /** How the client library words a broker's refusal of a login. */
    private static final List<String> REFUSALS = List.of("NOT_AUTHORIZED", "BAD_USER_NAME_OR_PASSWORD", "not authorized",
            "refused");

    private static Mosquitto tlsBroker(Path dir) throws Exception {
        return Mosquitto.start(dir, List.of("cafile " + certs.resolve("ca.pem"), "certfile " + certs.resolve("server.pem"),
                "keyfile " + certs.resolve("server.key"), "password_file " + certs.resolve("passwd")), false);
    }

    private static Daemon daemon(Mosquitto broker, String passwordFile, int port) throws Exception {
        String json = """
            {"system": "login-test", "status": {"port": 0},
             "interfaces": [{"id": "dev", "driver": "mqtt", "address": "%s", "reconnect": {"initialMs": 100, "maxMs": 400, "connectTimeoutMs": 15000},
               "params": {"tls": true, "caFile": "%s", "username": "habla", "passwordFile": "%s",
                          "readings": [{"channel": "level", "topic": "in/level"}]}}],
             "methods": [
               {"id": "raw", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@dev.level"}, "params": {"kind": "number"}},
               {"id": "up", "type": "pass-through", "layer": "processing", "inputs": {"in": "raw.out"}, "params": {"kind": "number"}},
               {"id": "level", "type": "pass-through", "layer": "virtual", "inputs": {"in": "up.out"}, "params": {"kind": "number"},
                "expose": {"port": %d, "name": "level"}}]}
            """.formatted(broker.address(), certs.resolve("ca.pem"), certs.resolve(passwordFile), port);
        return Daemon.start(new ConfigLoader(REGISTRY).parse(json), REGISTRY, EngineClock.system());
    }

    @Test
    void aBrokerThatTakesOnlyTlsAndAPasswordIsReachedWithTheConfiguredCaAndPasswordFile(@TempDir Path tmp)
            throws Exception {
        int port = DaemonProcess.freePorts(1)[0];
        try (Mosquitto broker = tlsBroker(tmp); Daemon daemon = daemon(broker, "password", port);
                ControlLines level = new ControlLines(port)) {
            level.staleness(false);
            String out = broker.client(10_000, "mosquitto_pub", "--cafile", certs.resolve("ca.pem").toString(),
                    "-u", "habla", "-P", "s3cret", "-t", "in/level", "-m", "42");
            assertThat(out).isBlank();
            assertThat(level.nextOfType("sample").path("value").asDouble()).isEqualTo(42);
        }
    }

    @Test
    void aWrongPasswordKeepsTheLinkDownAndSaysWhy(@TempDir Path tmp) throws Exception {
        int port = DaemonProcess.freePorts(1)[0];
        try (Mosquitto broker = tlsBroker(tmp); Daemon daemon = daemon(broker, "wrong-password", port)) {
            // Waits for an attempt the broker answered with its refusal (on a busy machine an attempt may also
            // time out first, which is another failure but not the one this test is about).
            long deadline = System.nanoTime() + 40_000_000_000L;
            JsonNode link = null;
            while (System.nanoTime() < deadline) {
                link = daemon.status().path("interfaces").get(0).path("connections").get(0);
                String error = link.path("lastError").asText();
                if (REFUSALS.stream().anyMatch(error::contains)) {
                    break;
                }
                Thread.sleep(20);
            }
            assertThat(link.path("up").asBoolean()).isFalse();
            assertThat(link.path("connects").asLong()).isZero();
            assertThat(link.path("lastError").asText()).containsAnyOf(REFUSALS.toArray(String[]::new));
        }
    }
}
