package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;

class StatusCommandTest {

    @Test
    void theSocketTableNamesWhoCommandsEachActuatingSocket() throws Exception {
        JsonNode st = new ObjectMapper().readTree("""
                {"system": "s", "watchdog": {}, "sockets": [
                  {"socket": "action", "port": 7004, "clients": 2, "control": {"holder":
                    {"connection": "action#3", "address": "127.0.0.1:53422"}, "since": "2025-01-01T10:00:00Z",
                    "silentMs": 120}},
                  {"socket": "say", "port": 7013, "clients": 0, "control": {"holder": null}},
                  {"socket": "drive", "port": 7014, "clients": 1, "auth": "required", "authFailures": 2, "control":
                    {"holder": {"client": "mdb", "connection": "drive#1", "address": "10.0.0.9:5000"},
                    "since": "2025-01-01T10:00:00Z", "silentMs": 5}},
                  {"socket": "distance_angle", "port": 7002, "clients": 1}],
                 "statusEndpoint": {"auth": "required", "authenticated": 4, "authFailures": 3}}
                """);
        StringWriter text = new StringWriter();
        StatusCommand.print(st, new PrintWriter(text));
        String[] lines = text.toString().split("\n");
        assertThat(text.toString()).contains("COMMANDED BY");
        assertThat(line(lines, "action")).endsWith("action#3 127.0.0.1:53422 since 2025-01-01T10:00:00Z (silent 120 ms)");
        assertThat(line(lines, "say")).endsWith("nobody");
        assertThat(line(lines, "drive")).endsWith("mdb drive#1 10.0.0.9:5000 since 2025-01-01T10:00:00Z (silent 5 ms)");
        assertThat(text.toString()).contains("authentication required on drive, the status endpoint; 5 failed attempts");
        assertThat(line(lines, "distance_angle")).endsWith("-");
    }

    @Test
    void theCommandAuthenticatesWhereTheEndpointRequiresIt(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        var credentials = org.habla.security.Credentials.of(java.util.Map.of("monitor", java.util.Map.entry(
                "monitor-token-0123456789", java.util.Map.of("@status", org.habla.security.Role.READ))), null);
        try (var server = new org.habla.status.StatusServer(new org.habla.config.StatusConfig("127.0.0.1", 7099),
                org.habla.config.Limits.DEFAULTS, () -> new ObjectMapper().createObjectNode().put("system", "guarded"),
                org.habla.security.PortAccess.authenticated("@status", credentials))) {
            server.startOnAnyPort();
            String port = "" + server.port();
            CommandRun without = CommandRun.of(new StatusCommand(), "--port", port, "--json", "--client", "");
            assertThat(without.exitCode()).isEqualTo(ExitCodes.RUNTIME_FAILURE);
            assertThat(without.err()).contains("requires authentication: give --client NAME and --token-file FILE");

            java.nio.file.Path token = java.nio.file.Files.writeString(dir.resolve("monitor.token"),
                    "monitor-token-0123456789\n");
            CommandRun with = CommandRun.of(new StatusCommand(), "--port", port, "--json", "--client", "monitor",
                    "--token-file", token.toString());
            assertThat(with.exitCode()).as(with.err()).isEqualTo(ExitCodes.OK);
            assertThat(with.out()).contains("\"system\" : \"guarded\"");

            java.nio.file.Files.writeString(token, "not-the-token-at-all\n");
            CommandRun wrong = CommandRun.of(new StatusCommand(), "--port", port, "--json", "--client", "monitor",
                    "--token-file", token.toString());
            assertThat(wrong.exitCode()).isEqualTo(ExitCodes.RUNTIME_FAILURE);
            assertThat(wrong.err()).contains("refused: auth_failed");
        }
    }

    private static String line(String[] lines, String socket) {
        for (String l : lines) {
            if (l.startsWith(socket + " ")) {
                return l.stripTrailing();
            }
        }
        throw new AssertionError("no line for socket " + socket);
    }
}
