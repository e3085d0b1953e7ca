package org.habla.config;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.BridgeProvider;
import org.habla.plugin.PluginRegistry;

/**
 * Reads the config's {@code bridges} array: each entry's keys, its type's params, a bridge made from them (cheap
 * by contract), and whether every socket it names is exposed by a method.
 */
final class BridgeReader {

    private final PluginRegistry registry;
    private final ConfigErrors errors;
    private final Path baseDir;

    BridgeReader(PluginRegistry registry, ConfigErrors errors, Path baseDir) {
        this.registry = registry;
        this.errors = errors;
        this.baseDir = baseDir;
    }

    /** The bridges that were read whole; errors for the others are recorded. */
    List<BridgeConfig> read(List<JsonNode> nodes, Set<String> socketNames) {
        List<BridgeConfig> bridges = new java.util.ArrayList<>();
        Map<String, JsonPath> ids = new HashMap<>();
        for (int i = 0; i < nodes.size(); i++) {
            JsonPath path = JsonPath.ROOT.field("bridges").index(i);
            bridge(nodes.get(i), path, socketNames).ifPresent(b -> {
                JsonPath earlier = ids.putIfAbsent(b.id(), path.field("id"));
                if (earlier != null) {
                    errors.add(path.field("id"), "duplicate bridge id '" + b.id() + "': already used at " + earlier);
                }
                bridges.add(b);
            });
        }
        return bridges;
    }

    private Optional<BridgeConfig> bridge(JsonNode node, JsonPath path, Set<String> socketNames) {
        Optional<CheckedObject> read = CheckedObject.of(node, path, errors);
        if (read.isEmpty()) {
            return Optional.empty();
        }
        CheckedObject o = read.get();
        o.allowOnly(ConfigLoader.BRIDGE_KEYS);
        String id = o.requiredString("id").filter(text -> {
            if (SourceSyntax.ID.matcher(text).matches()) {
                return true;
            }
            errors.add(path.field("id"), "'" + text + "' is not an id: " + SourceSyntax.ID_RULE);
            return false;
        }).orElse(null);
        BridgeProvider<?> provider = o.requiredString("type").flatMap(name -> {
            Optional<BridgeProvider<?>> p = registry.bridge(name);
            if (p.isEmpty()) {
                errors.add(path.field("type"), "unknown bridge type '" + name + "' (known: "
                        + (registry.bridges().isEmpty() ? "none registered" : String.join(", ", registry.bridges().keySet()))
                        + ")" + EntryReader.pluginsNote(registry));
            }
            return p;
        }).orElse(null);
        InterfaceAddress address = o.requiredString("address").flatMap(text -> {
            try {
                return Optional.of(InterfaceAddress.parse(text));
            } catch (IllegalArgumentException e) {
                errors.add(path.field("address"), "'" + text + "' is not an address (write host or host:port): "
                        + e.getMessage());
                return Optional.empty();
            }
        }).orElse(null);
        Reconnect reconnect = o.object("reconnect").map(r -> new EntryReader(registry, errors, baseDir).reconnect(r))
                .orElse(Reconnect.DEFAULTS);
        Record params = provider == null ? null
                : ParamsBinder.bind(o.node().get("params"), provider.paramsType(), path.field("params"), errors, baseDir)
                        .orElse(null);
        if (id == null || provider == null || address == null || params == null) {
            return Optional.empty();
        }
        Set<String> unknown = named(provider, params).stream().filter(s -> !socketNames.contains(s))
                .collect(Collectors.toCollection(java.util.TreeSet::new));
        if (!unknown.isEmpty()) {
            errors.add(path.field("params"), "names socket(s) " + unknown + " that no method exposes (exposed: "
                    + new java.util.TreeSet<>(socketNames) + ")");
            return Optional.empty();
        }
        return Optional.of(new BridgeConfig(id, provider.name(), address, params, reconnect));
    }

    @SuppressWarnings("unchecked")
    private static <P extends Record> Set<String> named(BridgeProvider<P> provider, Record params) {
        return provider.socketsNamed((P) params);
    }
}
