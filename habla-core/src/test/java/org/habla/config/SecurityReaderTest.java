package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The policy a config's ports and placements are checked against, as {@code habla check} reports it. */
class SecurityReaderTest {

    private static final String SECRET = "a-lab-worker-secret-of-some-length";

    private final ConfigLoader loader = new ConfigLoader(TestPlugins.registry());

    @TempDir
    Path dir;

    private Path credentials(String json) throws IOException {
        return Files.writeString(Files.createFile(dir.resolve("lab.credentials.json"),
                PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------"))), json);
    }

    private Path config(String status, String host, boolean withCredentials) throws IOException {
        return Files.writeString(dir.resolve("lab.json"), """
                {"system": "t", %s "status": %s,
                 "methods": [{"id": "action", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
                              "expose": {"port": 7004} %s}]}
                """.formatted(withCredentials ? "\"security\": {\"credentials\": \"lab.credentials.json\"}," : "",
                status, host == null ? "" : ", \"host\": \"" + host + "\""));
    }

    private static final String CLIENT = "{\"name\": \"mdb\", \"token\": \"a-token-of-twenty-chars\", "
            + "\"roles\": {\"*\": \"command\", \"@status\": \"read\"}}";

    @Test
    void theMonitorStaysOnLoopbackWhileTheStatusEndpointIsOnTheLabNetwork() throws Exception {
        credentials("{\"clients\": [" + CLIENT + "]}");
        HablaConfig cfg = loader.load(config("{\"bind\": \"0.0.0.0\", \"port\": 7099, \"monitorPort\": 7098}", null,
                true));
        assertThat(cfg.status().bind()).isEqualTo("0.0.0.0");
        assertThat(cfg.status().monitorBind()).isEqualTo("127.0.0.1");
    }

    @Test
    void aMonitorAskedBeyondLoopbackNeedsInsecureEvenWithCredentials() throws Exception {
        credentials("{\"clients\": [" + CLIENT + "]}");
        ConfigException e = catchThrowableOfType(ConfigException.class, () -> loader.load(config(
                "{\"bind\": \"0.0.0.0\", \"port\": 7099, \"monitorPort\": 7098, \"monitorBind\": \"0.0.0.0\"}", null,
                true)));
        assertThat(e).isNotNull();
        assertThat(e.errors()).singleElement().satisfies(err -> {
            assertThat(err.path()).isEqualTo("$.status.monitorBind");
            assertThat(err.message()).contains("the monitor has no authentication");
        });
    }

    @Test
    void aWorkerBeyondLoopbackNeedsTheWorkerSecretInTheCredentials() throws Exception {
        credentials("{\"clients\": [" + CLIENT + "]}");
        ConfigException e = catchThrowableOfType(ConfigException.class,
                () -> loader.load(config("{\"port\": 7099}", "10.0.0.21:7600", true)));
        assertThat(e).as("a config without workerSecret placing beyond loopback is refused").isNotNull();
        assertThat(e.errors()).singleElement().satisfies(err -> {
            assertThat(err.path()).isEqualTo("$.methods[0].host");
            assertThat(err.message()).contains("10.0.0.21:7600", "workerSecret");
        });
    }

    @Test
    void aWorkerBeyondLoopbackIsAcceptedWithTheSecretAndOnLoopbackWithout() throws Exception {
        credentials("{\"clients\": [" + CLIENT + "], \"workerSecret\": \"" + SECRET + "\"}");
        assertThat(loader.load(config("{\"port\": 7099}", "10.0.0.21:7600", true)).methods().get(0).host())
                .contains("10.0.0.21:7600");
        assertThat(loader.load(config("{\"port\": 7099}", "127.0.0.1:7600", false)).methods().get(0).host())
                .contains("127.0.0.1:7600");
    }
}
