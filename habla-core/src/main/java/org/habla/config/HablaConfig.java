package org.habla.config;

import java.util.List;
import java.util.Optional;

/**
 * A whole, valid config: the system's name, its interfaces, its methods, its bridges and the daemon's settings.
 * Only {@link ConfigLoader} makes these, after every check has passed.
 */
public record HablaConfig(String system, Limits limits, Safety safety, StatusConfig status,
        List<InterfaceConfig> interfaces, List<MethodConfig> methods, List<BridgeConfig> bridges) {

    public HablaConfig {
        interfaces = List.copyOf(interfaces);
        methods = List.copyOf(methods);
        bridges = List.copyOf(bridges);
    }

    /** A config without bridges. */
    public HablaConfig(String system, Limits limits, Safety safety, StatusConfig status,
            List<InterfaceConfig> interfaces, List<MethodConfig> methods) {
        this(system, limits, safety, status, interfaces, methods, List.of());
    }

    public Optional<MethodConfig> method(String id) {
        return methods.stream().filter(m -> m.id().equals(id)).findFirst();
    }

    public Optional<InterfaceConfig> iface(String id) {
        return interfaces.stream().filter(i -> i.id().equals(id)).findFirst();
    }
}
