package org.habla.daemon;

import static org.assertj.core.api.Assertions.assertThat;

import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.config.TestPlugins;
import org.junit.jupiter.api.Test;

class PortGuardsTest {

    private static final String CONFIG = """
            {"system": "t", "status": {"bind": "0.0.0.0", "port": 7099, "monitorPort": 7300, "monitorBind": "0.0.0.0"}, %s
             "interfaces": [{"id": "robot", "driver": "robot-sim", "address": "127.0.0.1:8101"}],
             "methods": [{"id": "action", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
                          "expose": {"port": 7004, "bind": "0.0.0.0"}},
                         {"id": "local", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
                          "expose": {"port": 7005}}]}
            """;

    @Test
    void anInsecureConfigIsWarnedOfEveryPortItLeavesOpenBeyondLoopback() throws Exception {
        HablaConfig insecure = new ConfigLoader(TestPlugins.registry())
                .parse(CONFIG.formatted("\"security\": {\"insecure\": true},"));
        assertThat(PortGuards.insecurePorts(insecure)).satisfiesExactly(
                w -> assertThat(w).startsWith("socket 'action' listens on 0.0.0.0:7004 without authentication"),
                w -> assertThat(w).startsWith("the status endpoint listens on 0.0.0.0:7099"),
                w -> assertThat(w).startsWith("the monitor listens on 0.0.0.0:7300"));
    }

    @Test
    void aPortThatAuthenticatesOverPlainTcpBeyondLoopbackIsWarnedOf(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        java.nio.file.Files.writeString(java.nio.file.Files.createFile(dir.resolve("c.json"),
                java.nio.file.attribute.PosixFilePermissions.asFileAttribute(
                        java.nio.file.attribute.PosixFilePermissions.fromString("rw-------"))), "{\"clients\": []}");
        HablaConfig secured = new ConfigLoader(TestPlugins.registry())
                .parse(CONFIG.formatted("\"security\": {\"credentials\": \"c.json\", \"insecure\": true},"), dir);
        assertThat(PortGuards.tokensInClear(secured)).satisfiesExactly(
                w -> assertThat(w).startsWith("socket 'action' on 0.0.0.0:7004 authenticates over plain TCP"),
                w -> assertThat(w).startsWith("the status endpoint on 0.0.0.0:7099 authenticates over plain TCP"));
        assertThat(PortGuards.insecurePorts(secured)).singleElement().asString().startsWith("the monitor");
    }
}
