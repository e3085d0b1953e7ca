package org.habla.config;

import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.habla.net.Limits;

/**
 * A whole, valid config: the system's name, its interfaces, its methods, its bridges and the daemon's settings.
 * Only {@link ConfigLoader} makes these, after every check has passed.
 */
public record HablaConfig(String system, Limits limits, Safety safety, StatusConfig status,
        List<InterfaceConfig> interfaces, List<MethodConfig> methods, List<BridgeConfig> bridges,
        SecurityConfig security) {

    public HablaConfig {
        interfaces = List.copyOf(interfaces);
        methods = List.copyOf(methods);
        bridges = List.copyOf(bridges);
        security = security == null ? SecurityConfig.DEFAULTS : security;
    }

    /** A config without security settings: loopback only, no credentials. */
    public HablaConfig(String system, Limits limits, Safety safety, StatusConfig status,
            List<InterfaceConfig> interfaces, List<MethodConfig> methods, List<BridgeConfig> bridges) {
        this(system, limits, safety, status, interfaces, methods, bridges, SecurityConfig.DEFAULTS);
    }

    /** A config without bridges. */
    public HablaConfig(String system, Limits limits, Safety safety, StatusConfig status,
            List<InterfaceConfig> interfaces, List<MethodConfig> methods) {
        this(system, limits, safety, status, interfaces, methods, List.of());
    }

    public Optional<MethodConfig> method(String id) {
        return methods.stream().filter(m -> m.id().equals(id)).findFirst();
    }

    /**
     * The inputs of method {@code id} whose wires lie on a declared cycle: the engine delivers them as
     * {@code latest} whatever the method type asks for.
     */
    public Set<String> cycleInputs(String id) {
        return WiringCycles.of(methods).cycleInputs(id);
    }

    public Optional<InterfaceConfig> iface(String id) {
        return interfaces.stream().filter(i -> i.id().equals(id)).findFirst();
    }
}
