package org.habla.security;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Set;
import org.habla.config.ConfigException;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.config.TestPlugins;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CredentialsFileTest {

    private static final String TOKEN = "a-token-of-twenty-chars";

    @TempDir
    Path dir;

    private Path file(String text, String mode) throws Exception {
        Path f = dir.resolve("lab.credentials.json");
        Files.deleteIfExists(f);
        Files.writeString(Files.createFile(f, PosixFilePermissions.asFileAttribute(
                PosixFilePermissions.fromString(mode))), text);
        return f;
    }

    @Test
    void aGoodFileVerifiesItsClientsTokensAndRolesAndNothingElse() throws Exception {
        Credentials c = CredentialsFile.read(file("""
                {"clients": [{"name": "mdb", "token": "%s", "roles": {"action": "command", "*": "read"}}],
                 "workerSecret": "a-worker-secret-0123"}
                """.formatted(TOKEN), "rw-------"), Set.of("action", "ranges"));
        Principal mdb = c.verify("mdb", TOKEN).orElseThrow();
        assertThat(mdb.roleOn("action")).contains(Role.COMMAND);
        assertThat(mdb.roleOn("ranges")).contains(Role.READ);
        assertThat(mdb.roleOn(Principal.STATUS)).isEmpty();
        assertThat(c.verify("mdb", TOKEN + "x")).isEmpty();
        assertThat(c.verify("nobody", TOKEN)).isEmpty();
        assertThat(c.workerSecret()).isPresent();
        assertThat(c.toString()).doesNotContain(TOKEN, "a-worker-secret");
    }

    @Test
    void everyProblemIsNamedAtItsPlaceWithoutQuotingASecret() throws Exception {
        var e = catchThrowableOfType(() -> CredentialsFile.read(file("""
                {"clients": [
                   {"name": "mdb", "token": "short", "roles": {"actoin": "command"}},
                   {"name": "viewer", "token": "%s", "roles": {"@status": "command", "*": "drive"}},
                   {"name": "viewer", "token": "%s", "roles": {"*": "read"}, "colour": "red"}],
                 "workerSecret": 5}
                """.formatted(TOKEN, TOKEN), "rw-------"), Set.of("action")), CredentialsFile.Invalid.class);
        assertThat(e.problems()).containsExactlyInAnyOrder(
                "$.clients[0].token: must have 16 to 1024 characters, had 5 (make one with: openssl rand -base64 24)",
                "$.clients[0].roles.actoin: the config exposes no socket 'actoin'; keys are socket names, \"*\" and "
                        + "\"@status\"; sockets are [action]",
                "$.clients[1].roles.@status: the status endpoint takes \"read\" only",
                "$.clients[1].roles.*: must be \"read\" or \"command\", was \"drive\"",
                "$.clients[2].colour: unknown key; allowed are [name, roles, token]",
                "$.workerSecret: must be a string");
        assertThat(e.getMessage()).doesNotContain("short", TOKEN);
    }

    @Test
    void aFileOthersMayReadIsRefused() throws Exception {
        Path f = file("{\"clients\": []}", "rw-r--r--");
        var e = catchThrowableOfType(() -> CredentialsFile.read(f, Set.of()), CredentialsFile.Invalid.class);
        assertThat(e.problems()).singleElement().asString().contains("others may read it", "chmod 600 " + f);
    }

    @Test
    void aSocketBeyondLoopbackIsAcceptedWithCredentialsOrWhenInsecureAndRefusedOtherwise() throws Exception {
        file("{\"clients\": [{\"name\": \"mdb\", \"token\": \"" + TOKEN + "\", \"roles\": {\"*\": \"command\"}}]}",
                "rw-------");
        String config = """
                {"system": "t", %s
                 "interfaces": [{"id": "robot", "driver": "robot-sim", "address": "127.0.0.1:8101"}],
                 "methods": [{"id": "action", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
                              "expose": {"port": 7004, "bind": "0.0.0.0"}}]}
                """;
        ConfigLoader loader = new ConfigLoader(TestPlugins.registry());
        HablaConfig secured = loader.parse(config.formatted(
                "\"security\": {\"credentials\": \"lab.credentials.json\"},"), dir);
        assertThat(secured.security().authenticates("0.0.0.0")).isTrue();
        assertThat(secured.security().authenticates("127.0.0.1")).isFalse();
        assertThat(secured.security().auditLog()).isEqualTo(dir.resolve("habla-audit.log"));
        assertThat(loader.parse(config.formatted("\"security\": {\"insecure\": true},"), dir).security().insecure())
                .isTrue();
        var refused = catchThrowableOfType(() -> loader.parse(config.formatted(""), dir), ConfigException.class);
        assertThat(refused.errors()).singleElement().satisfies(err ->
                assertThat(err.path()).isEqualTo("$.methods[0].expose.bind"));
    }
}
