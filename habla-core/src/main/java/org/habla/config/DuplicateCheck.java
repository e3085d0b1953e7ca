package org.habla.config;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Finds what must be unique in a config and is not: method ids, interface ids, socket names, and TCP
 * ports (every {@code expose.port} and a non-zero {@code status.port}). Each repeat is reported at the
 * later occurrence, naming the first.
 */
final class DuplicateCheck {

    private final ConfigErrors errors;

    DuplicateCheck(ConfigErrors errors) {
        this.errors = errors;
    }

    void run(StatusConfig status, boolean statusGiven, List<InterfaceEntry> interfaces, List<MethodEntry> methods) {
        Map<String, JsonPath> interfaceIds = new HashMap<>();
        for (InterfaceEntry i : interfaces) {
            if (i.id() != null) {
                first(interfaceIds, i.id(), i.path().field("id"), "interface id '" + i.id() + "'");
            }
        }
        Map<String, JsonPath> methodIds = new HashMap<>();
        Map<String, JsonPath> names = new HashMap<>();
        Map<String, JsonPath> ports = new HashMap<>();
        String statusWhere = statusGiven ? "$.status.port" : "$.status.port (the status endpoint's default)";
        if (status.port() != 0) {
            ports.put(Integer.toString(status.port()), new JsonPath(statusWhere));
        }
        if (status.monitorPort() != 0) {
            first(ports, Integer.toString(status.monitorPort()), new JsonPath("$.status.monitorPort"),
                    "port " + status.monitorPort());
        }
        for (MethodEntry m : methods) {
            if (m.id() != null) {
                first(methodIds, m.id(), m.path().field("id"), "method id '" + m.id() + "'");
            }
            m.expose().ifPresent(e -> {
                JsonPath expose = m.path().field("expose");
                first(ports, Integer.toString(e.port()), expose.field("port"), "port " + e.port());
                first(names, e.name(), expose.field("name"), "socket name '" + e.name() + "'");
            });
        }
    }

    private void first(Map<String, JsonPath> seen, String key, JsonPath here, String what) {
        JsonPath earlier = seen.putIfAbsent(key, here);
        if (earlier != null) {
            errors.add(here, "duplicate " + what + ": already used at " + earlier);
        }
    }
}
