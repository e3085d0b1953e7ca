package org.habla.cli;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.habla.command.ExitCodes;
import org.habla.net.Limits;
import org.habla.config.TestPlugins;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.testing.DaemonProcess;
import org.habla.worker.WorkerServer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

@Timeout(30)
class RunPlacementTest {

    @Test
    void runExitsWithTwoWhenAWorkerCannotRunAMethodPlacedOnIt(@TempDir Path dir) throws Exception {
        EngineClock clock = EngineClock.system();
        try (WorkerServer worker = new WorkerServer(PluginRegistry.of(List.of(), List.of()), "127.0.0.1", 0, clock,
                Limits.DEFAULTS)) {
            worker.start();
            ObjectMapper json = new ObjectMapper();
            ObjectNode config = (ObjectNode) json.readTree(getClass().getResource("/configs/valid/pioneer-like.json"));
            // The file places 'action' on a worker at 7600, which may not be there: this test starts its own.
            config.withArray("methods").forEach(m -> ((ObjectNode) m).remove("host"));
            ((ObjectNode) config.withArray("methods").get(1)).put("host", "127.0.0.1:" + worker.port());
            // Free ports instead of the file's 7002, 7004, 7199: a daemon running on this machine may hold those.
            int[] free = DaemonProcess.freePorts(config.withArray("methods").size() + 1);
            int next = 0;
            for (var m : config.withArray("methods")) {
                if (m.has("expose")) {
                    ((ObjectNode) m.get("expose")).put("port", free[next++]);
                }
            }
            ((ObjectNode) config.get("status")).put("port", free[next]);
            Path file = dir.resolve("placed.json");
            Files.writeString(file, json.writeValueAsString(config));

            CommandRun run = CommandRun.of(new RunCommand(TestPlugins.registry()), file.toString());

            assertThat(run.exitCode()).isEqualTo(ExitCodes.USAGE_OR_CONFIG);
            assertThat(run.err().lines().toList()).containsExactly(
                    "habla run: method 'nearest' is placed on worker 127.0.0.1:" + worker.port()
                            + ", but the worker cannot run method type 'nearest-distance' (it runs: nothing)",
                    "habla run: the daemon does not start");
        } finally {
            clock.close();
        }
    }

    @Test
    void workerIsASubcommandOfHabla() {
        assertThat(Habla.commandLine().getSubcommands()).containsKey("worker");
    }
}
