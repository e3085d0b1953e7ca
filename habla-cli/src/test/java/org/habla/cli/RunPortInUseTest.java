package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import org.habla.command.ExitCodes;
import org.habla.config.TestPlugins;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** A port another program holds is a config error: exit 2 with the port's JSON path, and nothing served. */
@Timeout(30)
class RunPortInUseTest {

    private static final InetAddress LOOPBACK = InetAddress.getLoopbackAddress();

    private static Path config(Path dir, int actionPort, int echoPort, int statusPort) throws IOException {
        Path file = dir.resolve("ports.json");
        Files.writeString(file, """
                {"system": "ports", "status": {"port": %d}, "methods": [
                  {"id": "action", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
                   "expose": {"port": %d}},
                  {"id": "echo", "type": "relay", "layer": "virtual", "inputs": {"in": "action.velocity"},
                   "expose": {"port": %d}}]}
                """.formatted(statusPort, actionPort, echoPort));
        return file;
    }

    private static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, LOOPBACK)) {
            return s.getLocalPort();
        }
    }

    private static boolean accepts(int port) {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(LOOPBACK, port), 1_000);
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    @Test
    void aControlPortInUseExitsWithTwoAtItsJsonPathAndLeavesTheOtherPortsUnbound(@TempDir Path dir) throws Exception {
        int free = freePort();
        try (ServerSocket taken = new ServerSocket(0, 1, LOOPBACK)) {
            Path file = config(dir, free, taken.getLocalPort(), 0);

            CommandRun run = CommandRun.of(new RunCommand(TestPlugins.registry()), file.toString());

            assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
            assertThat(run.err().lines().toList()).hasSize(2);
            assertThat(run.err().lines().toList().get(0)).isEqualTo(file + ": 1 error; the daemon does not start:");
            assertThat(run.err().lines().toList().get(1)).startsWith("$.methods[1].expose.port: control socket 'echo'"
                    + " cannot listen on 127.0.0.1:" + taken.getLocalPort() + ": ");
            assertThat(accepts(free)).as("the free port of the config is not left listening").isFalse();
        }
    }

    @Test
    void aStatusPortInUseIsAConfigErrorToo(@TempDir Path dir) throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, LOOPBACK)) {
            Path file = config(dir, freePort(), freePort(), taken.getLocalPort());

            CommandRun run = CommandRun.of(new RunCommand(TestPlugins.registry()), file.toString());

            assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
            assertThat(run.err()).contains("$.status.port: the status endpoint cannot listen on 127.0.0.1:"
                    + taken.getLocalPort());
        }
    }

    @Test
    void aMonitorPortInUseIsAConfigErrorAtItsPath(@TempDir Path dir) throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, LOOPBACK)) {
            Path file = dir.resolve("monitor.json");
            Files.writeString(file, """
                    {"system": "ports", "status": {"port": 0, "monitorPort": %d}, "methods": [
                      {"id": "action", "type": "action", "layer": "virtual", "inputs": {"action": "control"},
                       "expose": {"port": %d}}]}
                    """.formatted(taken.getLocalPort(), freePort()));

            CommandRun run = CommandRun.of(new RunCommand(TestPlugins.registry()), file.toString());

            assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
            assertThat(run.err()).contains("$.status.monitorPort: the monitor cannot listen on 127.0.0.1:"
                    + taken.getLocalPort());
        }
    }

    @Test
    void aRecordingIsNotStartedWhenAPortIsInUse(@TempDir Path dir) throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, LOOPBACK)) {
            Path file = config(dir, freePort(), taken.getLocalPort(), 0);
            Path recording = dir.resolve("run.habla");

            CommandRun run = CommandRun.of(new RunCommand(TestPlugins.registry()), file.toString(),
                    "--record", recording.toString());

            assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
            assertThat(recording).doesNotExist();
        }
    }
}
