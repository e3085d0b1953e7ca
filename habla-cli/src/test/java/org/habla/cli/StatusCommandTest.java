package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import org.habla.command.ExitCodes;
import org.habla.testing.LabCertificate;
import org.junit.jupiter.api.Test;

class StatusCommandTest {

    @Test
    void theCommandAuthenticatesWhereTheEndpointRequiresIt(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        var credentials = org.habla.security.Credentials.of(java.util.Map.of("monitor", java.util.Map.entry(
                "monitor-token-0123456789", java.util.Map.of("@status", org.habla.security.Role.READ))), null);
        try (var server = new org.habla.status.StatusServer(new org.habla.config.StatusConfig("127.0.0.1", 7099),
                org.habla.net.Limits.DEFAULTS, () -> new ObjectMapper().createObjectNode().put("system", "guarded"),
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

    @Test
    void theCommandFindsTheStatusEndpointFromTheDaemonsConfig(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        int port = org.habla.testing.DaemonProcess.freePorts(1)[0];
        java.nio.file.Path config = java.nio.file.Files.writeString(dir.resolve("room.json"), """
                {"system": "room", "security": {"insecure": true}, "status": {"bind": "0.0.0.0", "port": %d}}
                """.formatted(port));
        try (var server = new org.habla.status.StatusServer(new org.habla.config.StatusConfig("0.0.0.0", port),
                () -> new ObjectMapper().createObjectNode().put("system", "room"))) {
            server.start();
            CommandRun positional = CommandRun.of(new StatusCommand(), config.toString(), "--json");
            assertThat(positional.exitCode()).as(positional.err()).isEqualTo(ExitCodes.OK);
            assertThat(positional.out()).contains("\"system\" : \"room\"");

            CommandRun option = CommandRun.of(new StatusCommand(), "--config", config.toString(), "--json");
            assertThat(option.exitCode()).as(option.err()).isEqualTo(ExitCodes.OK);
            assertThat(option.out()).contains("\"system\" : \"room\"");
        }
        CommandRun gone = CommandRun.of(new StatusCommand(), config.toString());
        assertThat(gone.exitCode()).isEqualTo(ExitCodes.RUNTIME_FAILURE);
        assertThat(gone.err()).contains("no daemon status at 127.0.0.1:" + port, "status.port of " + config);
    }

    @Test
    void aConfigWhoseStatusSpeaksTlsIsReadTrustingItsOwnCertificate(@org.junit.jupiter.api.io.TempDir
            java.nio.file.Path dir) throws Exception {
        LabCertificate lab = LabCertificate.make(dir, "lab");
        java.nio.file.Path cert = lab.certificate();
        java.nio.file.Path key = lab.key();
        int port = org.habla.testing.DaemonProcess.freePorts(1)[0];
        java.nio.file.Path config = java.nio.file.Files.writeString(dir.resolve("lab.json"), """
                {"system": "lab", "security": {"tls": {"certificate": "lab.crt", "key": "lab.key"}},
                 "status": {"port": %d, "tls": true}}
                """.formatted(port));
        try (var server = new org.habla.status.StatusServer(new org.habla.config.StatusConfig("127.0.0.1", port),
                org.habla.net.Limits.DEFAULTS, () -> new ObjectMapper().createObjectNode().put("system", "lab"),
                org.habla.security.PortAccess.open("@status"), org.habla.security.Tls.server(cert, key))) {
            server.start();
            CommandRun run = CommandRun.of(new StatusCommand(), config.toString(), "--json");
            assertThat(run.exitCode()).as(run.err()).isEqualTo(ExitCodes.OK);
            assertThat(run.out()).contains("\"system\" : \"lab\"");
        }
    }

    @Test
    void theStatusEndpointOverTlsAuthenticatesTheCommandAndTellsAPlainClient(@org.junit.jupiter.api.io.TempDir
            java.nio.file.Path dir) throws Exception {
        LabCertificate lab = LabCertificate.make(dir, "lab");
        String token = "mdb-token-0123456789abcdef";
        var credentials = org.habla.security.Credentials.of(java.util.Map.of("mdb", java.util.Map.entry(token,
                java.util.Map.of("@status", org.habla.security.Role.READ))), null);
        try (var status = new org.habla.status.StatusServer(new org.habla.config.StatusConfig("127.0.0.1", 7099),
                org.habla.net.Limits.DEFAULTS, () -> new ObjectMapper().createObjectNode().put("system", "over-tls"),
                org.habla.security.PortAccess.authenticated("@status", credentials),
                org.habla.security.Tls.server(lab.certificate(), lab.key()))) {
            status.startOnAnyPort();
            java.nio.file.Path tokenFile = java.nio.file.Files.writeString(dir.resolve("mdb.token"), token + "\n");
            CommandRun run = CommandRun.of(new StatusCommand(), "--port", "" + status.port(), "--json", "--client",
                    "mdb", "--token-file", tokenFile.toString(), "--tls-trust", lab.certificate().toString());
            assertThat(run.exitCode()).as(run.err()).isEqualTo(ExitCodes.OK);
            assertThat(run.out()).contains("\"system\" : \"over-tls\"");
            try (var plain = new java.net.Socket("127.0.0.1", status.port())) {
                plain.setSoTimeout(10_000);
                String line = new java.io.BufferedReader(new java.io.InputStreamReader(plain.getInputStream(),
                        java.nio.charset.StandardCharsets.UTF_8)).readLine();
                assertThat(line).contains("\"code\":\"tls_required\"");
            }
        }
    }

    @Test
    void aConfigWithoutAStatusEndpointIsSaidSo(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        java.nio.file.Path config = java.nio.file.Files.writeString(dir.resolve("quiet.json"),
                "{\"system\": \"quiet\", \"status\": {\"port\": 0}}");
        CommandRun run = CommandRun.of(new StatusCommand(), config.toString());
        assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
        assertThat(run.err()).contains("turns the status endpoint off (status.port 0)");

        CommandRun broken = CommandRun.of(new StatusCommand(), dir.resolve("missing.json").toString());
        assertThat(broken.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
    }
}
