package org.habla.sim.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.config.MethodConfig;
import org.habla.graph.EngineClock;
import org.habla.graph.MethodGraph;
import org.habla.net.ControlPoint;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;

/**
 * The control contract (docs/control-contract.md): config/pioneer.json, config/aibo.json and config/ros2-base.json
 * expose the same sockets — names, ports, directions and value kinds — so one control program drives any of them.
 */
class ControlContractTest {

    private static final List<String> CONTRACT = List.of("command", "distance_angle", "reward", "action");
    private static final Map<String, Integer> PORTS = Map.of("command", 7001, "distance_angle", 7002, "reward", 7003,
            "action", 7004);

    @Test
    void everyRobotExposesTheSameContract() throws Exception {
        Map<String, String> pioneer = contract("pioneer");
        Map<String, String> aibo = contract("aibo");
        assertThat(pioneer).containsOnlyKeys(CONTRACT);
        assertThat(aibo).isEqualTo(pioneer);
        assertThat(contract("ros2-base")).isEqualTo(pioneer);
    }

    /** Socket name → "port, layer, control inputs' kinds, outputs' kinds" as the daemon would serve it. */
    private static Map<String, String> contract(String robot) throws Exception {
        PluginRegistry registry = PluginRegistry.discover(ControlContractTest.class.getClassLoader());
        HablaConfig config = new ConfigLoader(registry).load(SimulatedDeployment.HOME.resolve("config/" + robot + ".json"));
        Map<String, Integer> ports = new TreeMap<>();
        for (MethodConfig m : config.methods()) {
            m.expose().ifPresent(e -> ports.put(e.name(), e.port()));
        }
        Map<String, String> out = new TreeMap<>();
        try (MethodGraph graph = MethodGraph.build(config, registry, EngineClock.system())) {
            for (ControlPoint p : graph.controlPoints()) {
                if (!CONTRACT.contains(p.name())) {
                    assertThat(ports.get(p.name())).as("%s: extras live from port 7010 up", p.name())
                            .isGreaterThanOrEqualTo(7010);
                    continue;
                }
                assertThat(ports.get(p.name())).as("%s port in %s", p.name(), robot).isEqualTo(PORTS.get(p.name()));
                out.put(p.name(), ports.get(p.name()) + ", " + p.layer() + ", in "
                        + p.controlInputs().stream().map(i -> i.kind().wireName()).toList() + ", out "
                        + p.outputs().stream().map(o -> o.name() + ":" + o.kind().wireName()).sorted().toList());
            }
        }
        return out;
    }
}
