package org.habla.sim.daemon;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.function.Predicate;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.daemon.Daemon;
import org.habla.graph.EngineClock;
import org.habla.plugin.PluginRegistry;
import org.habla.sim.pioneer.PioneerSim;
import org.habla.sim.pioneer.PioneerSimOptions;
import org.habla.sim.world.TruthClient;
import org.habla.sim.world.World;
import org.junit.jupiter.api.Test;

/** The HABLA daemon with the Pioneer's three interfaces, connected to the simulator's sockets. */
class DaemonAgainstPioneerSimTest {

    @Test
    void theDaemonLinksToTheSimulatedRobotMicrophoneAndKeyboard() throws Exception {
        try (PioneerSim sim = PioneerSim.start(PioneerSimOptions.forTest(World.builtIn("pioneer-room"), 2))) {
            String config = """
                    {"system": "pioneer-sim-check", "status": {"port": 0},
                     "interfaces": [
                       {"id": "robot", "driver": "pioneer", "address": "127.0.0.1:%d", "params": {"keepAlivePeriodMs": 250}},
                       {"id": "mic", "driver": "pcm-stream", "address": "127.0.0.1:%d"},
                       {"id": "keys", "driver": "text-lines", "address": "127.0.0.1:%d"}],
                     "methods": [
                       {"id": "odometry", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@robot.odometry"}},
                       {"id": "sound", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@mic.audio"}},
                       {"id": "typed", "type": "channel", "layer": "sensors_actuators", "inputs": {"in": "@keys.lines"}}]}
                    """.formatted(sim.arcosPort(), sim.micPort(), sim.keysPort());
            PluginRegistry registry = PluginRegistry.discover(getClass().getClassLoader());
            HablaConfig cfg = new ConfigLoader(registry).parse(config);
            try (Daemon daemon = Daemon.start(cfg, registry, EngineClock.system())) {
                ObjectNode status = awaitStatus(daemon, st -> readings(st, "robot", "odometry") >= 5
                        && readings(st, "robot", "sonar") >= 1 && readings(st, "mic", "audio") >= 5);
                assertThat(status.at("/interfaces/0/robot/subclass").asText()).isEqualTo("p2dx");
                assertThat(status.at("/interfaces/0/malformed").asLong()).isZero();
                try (TruthClient truth = new TruthClient(sim.truthPort())) {
                    assertThat(truth.op("{\"op\":\"reward\",\"value\":-1}").has("ok")).isTrue();
                }
                awaitStatus(daemon, st -> readings(st, "keys", "lines") == 1);
            }
        }
    }

    private static ObjectNode awaitStatus(Daemon daemon, Predicate<ObjectNode> test) throws InterruptedException {
        long deadline = System.currentTimeMillis() + 15_000;
        ObjectNode status = daemon.status();
        while (!test.test(status)) {
            assertThat(System.currentTimeMillis()).as("status never matched: %s", status).isLessThan(deadline);
            Thread.sleep(50);
            status = daemon.status();
        }
        return status;
    }

    private static long readings(ObjectNode status, String iface, String channel) {
        for (var i : status.path("interfaces")) {
            if (i.path("id").asText().equals(iface)) {
                return i.path("readings").path(channel).asLong();
            }
        }
        return -1;
    }
}
