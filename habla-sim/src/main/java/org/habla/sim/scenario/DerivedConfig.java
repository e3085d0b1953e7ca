package org.habla.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.Map;

/**
 * The robot's config as a scenario runs it: every port moved by the scenario's port offset (so a run
 * can sit beside another on one machine) and the drivers' own keep-alive periods shortened by the time
 * scale (the simulated robot's watchdog runs that much faster). The engine's time is scaled by
 * {@code habla run --time-scale}, not here. The robot's config file itself is never changed.
 */
public final class DerivedConfig {

    /** Driver parameters that are wall-clock periods the simulated robot checks in its own, sped-up time. */
    private static final String[] DRIVER_PERIODS = {"keepAlivePeriodMs", "walkResendMs"};

    /** Tekkotsu's server ports, which a config may leave at their defaults. */
    private static final Map<String, Integer> TEKKOTSU_PORTS = Map.of("worldStatePort", 10031, "walkPort", 10050,
            "headPort", 10052, "eStopPort", 10053, "microphonePort", 10070, "speakerPort", 10071, "cameraPort", 10011,
            "controllerPort", 10020);

    private DerivedConfig() {
    }

    public static Path write(Path robotConfig, double speed, int portOffset, Path out) throws IOException {
        ObjectMapper json = new ObjectMapper();
        ObjectNode root = (ObjectNode) json.readTree(Files.readString(robotConfig));
        root.put("description", "Derived by habla scenario from " + robotConfig.getFileName() + " (speed " + speed
                + ", port offset " + portOffset + ")");
        root.remove("$schema");
        for (JsonNode iface : root.path("interfaces")) {
            ObjectNode i = (ObjectNode) iface;
            String address = i.path("address").asText();
            int colon = address.lastIndexOf(':');
            if (colon > 0) {
                i.put("address", address.substring(0, colon) + ":" + (Integer.parseInt(address.substring(colon + 1)) + portOffset));
            }
            ObjectNode params = i.has("params") ? (ObjectNode) i.get("params") : i.putObject("params");
            if (i.path("driver").asText().equals("tekkotsu")) {
                TEKKOTSU_PORTS.forEach((k, v) -> params.put(k, params.path(k).asInt(v) + portOffset));
            }
            for (String k : DRIVER_PERIODS) {
                if (params.has(k)) {
                    params.put(k, Math.max(10, Math.round(params.get(k).asDouble() / speed)));
                }
            }
            if (i.path("driver").asText().equals("pioneer") && !params.has("keepAlivePeriodMs")) {
                params.put("keepAlivePeriodMs", Math.max(10, Math.round(500 / speed)));
            }
            if (i.path("driver").asText().equals("tekkotsu") && !params.has("walkResendMs")) {
                params.put("walkResendMs", Math.max(100, Math.round(1000 / speed)));
            }
        }
        Path base = robotConfig.toAbsolutePath().getParent();
        for (JsonNode m : root.path("methods")) {
            if (m.path("params").isObject()) {
                // The derived config lives elsewhere: files named relative to the robot's config stay found.
                ObjectNode params = (ObjectNode) m.get("params");
                params.properties().forEach(e -> {
                    if (e.getValue().isTextual() && e.getValue().asText().contains("/")
                            && !Path.of(e.getValue().asText()).isAbsolute()
                            && Files.isRegularFile(base.resolve(e.getValue().asText()))) {
                        params.put(e.getKey(), base.resolve(e.getValue().asText()).normalize().toString());
                    }
                });
            }
            JsonNode expose = m.path("expose");
            if (expose.isObject() && expose.has("port")) {
                ((ObjectNode) expose).put("port", expose.get("port").asInt() + portOffset);
            }
        }
        if (root.path("status").isObject() && root.path("status").has("port")) {
            ObjectNode s = (ObjectNode) root.get("status");
            s.put("port", s.get("port").asInt() + portOffset);
            if (s.path("monitorPort").asInt() > 0) {
                s.put("monitorPort", s.get("monitorPort").asInt() + portOffset);
            }
        } else {
            root.putObject("status").put("port", 7099 + portOffset);
        }
        Files.writeString(out, json.writerWithDefaultPrettyPrinter().writeValueAsString(root));
        return out;
    }

    /** The exposed port of the socket named {@code name} in a config, or -1. */
    public static int exposedPort(Path config, String name) throws IOException {
        JsonNode root = new ObjectMapper().readTree(Files.readString(config));
        for (Iterator<JsonNode> it = root.path("methods").elements(); it.hasNext(); ) {
            JsonNode m = it.next();
            JsonNode e = m.path("expose");
            if (e.isObject() && (e.path("name").asText(m.path("id").asText())).equals(name)) {
                return e.path("port").asInt(-1);
            }
        }
        return -1;
    }
}
