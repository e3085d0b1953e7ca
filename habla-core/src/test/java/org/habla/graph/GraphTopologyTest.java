package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.config.Source;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;

class GraphTopologyTest {

    /** robot → s → p → v (exposed); cmd (control) → fwd → act → robot's motor; p also feeds fwd2, which nothing reads. */
    private static GraphTopology topology() throws Exception {
        PluginRegistry base = TestMethods.registry();
        PluginRegistry registry = PluginRegistry.of(new ArrayList<>(base.methods().values()),
                List.of(new LineDriver.Provider()));
        HablaConfig config = new ConfigLoader(registry).parse("""
                {"system": "topology", "status": {"port": 0},
                 "interfaces": [{"id": "robot", "driver": "lines-test", "address": "127.0.0.1:9"}],
                 "methods": [
                   {"id": "s", "type": "add-one-sensor", "layer": "sensors_actuators", "inputs": {"in": "@robot.value"}},
                   {"id": "p", "type": "add-one-processing", "layer": "processing", "inputs": {"in": "s.out"}},
                   {"id": "v", "type": "add-one-virtual", "layer": "virtual", "inputs": {"in": "p.out"},
                    "expose": {"port": 7801, "name": "v"}},
                   {"id": "cmd", "type": "command-virtual", "layer": "virtual", "inputs": {"in": "control"},
                    "expose": {"port": 7802, "name": "cmd"}},
                   {"id": "fwd", "type": "forward-processing", "layer": "processing", "inputs": {"in": "cmd.out"}},
                   {"id": "act", "type": "forward-actuator", "layer": "sensors_actuators", "inputs": {"in": "fwd.out"},
                    "commands": {"out": "@robot.motor"}},
                   {"id": "fwd2", "type": "forward-processing", "layer": "processing", "inputs": {"in": "p.out"}}
                 ]}
                """);
        return new GraphTopology(config);
    }

    @Test
    void aMethodIsReachedByTheChannelsAndInterfacesUpstreamOfItOnly() throws Exception {
        GraphTopology t = topology();
        assertThat(t.upstreamChannels("v")).containsExactly(new Source.Channel("robot", "value"));
        assertThat(t.upstreamInterfaces("v")).containsExactly("robot");
        assertThat(t.upstreamInterfaces("act")).as("fed by control only").isEmpty();
    }

    @Test
    void feedingAndDownstreamFollowTheWiresBothWays() throws Exception {
        GraphTopology t = topology();
        assertThat(t.feeding("v")).containsExactlyInAnyOrder("v", "p", "s");
        assertThat(t.feeding("act")).containsExactlyInAnyOrder("act", "fwd", "cmd");
        assertThat(t.downstream("s")).containsExactlyInAnyOrder("s", "p", "v", "fwd2");
        assertThat(t.downstream("cmd")).containsExactlyInAnyOrder("cmd", "fwd", "act");
    }

    @Test
    void onlyAMethodThatLeadsToACommandChannelActuates() throws Exception {
        GraphTopology t = topology();
        assertThat(t.actuates("cmd")).isTrue();
        assertThat(t.actuates("act")).isTrue();
        assertThat(t.actuates("s")).isFalse();
        assertThat(t.actuates("fwd2")).isFalse();
    }
}
