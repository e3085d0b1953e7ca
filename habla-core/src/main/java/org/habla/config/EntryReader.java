package org.habla.config;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.method.Layer;
import org.habla.method.Ports;
import org.habla.net.Expose;
import org.habla.plugin.DriverProvider;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;

/**
 * Reads the elements of the {@code interfaces} and {@code methods} arrays: their keys and values, their
 * type's params, the ports the method type lists for them (no method is made), and a driver made from them
 * (cheap by contract), so that the cross checks can see the ports and channels.
 */
final class EntryReader {

    private final PluginRegistry registry;
    private final ConfigErrors errors;

    private final java.nio.file.Path baseDir;

    EntryReader(PluginRegistry registry, ConfigErrors errors, java.nio.file.Path baseDir) {
        this.baseDir = baseDir;
        this.registry = registry;
        this.errors = errors;
    }

    InterfaceEntry iface(JsonNode node, JsonPath path) {
        Optional<CheckedObject> read = CheckedObject.of(node, path, errors);
        if (read.isEmpty()) {
            return new InterfaceEntry(path, null, null, null, null, Reconnect.DEFAULTS, null);
        }
        CheckedObject o = read.get();
        o.allowOnly(ConfigLoader.INTERFACE_KEYS);
        String id = id(o);
        DriverProvider<?> provider = o.requiredString("driver").flatMap(name -> {
            Optional<DriverProvider<?>> p = registry.driver(name);
            if (p.isEmpty()) {
                errors.add(o.path().field("driver"), "unknown driver type '" + name + "' (known: "
                        + known(registry.drivers()) + ")" + pluginsNote(registry));
            }
            return p;
        }).orElse(null);
        InterfaceAddress address = o.requiredString("address").flatMap(text -> {
            try {
                return Optional.of(InterfaceAddress.parse(text));
            } catch (IllegalArgumentException e) {
                errors.add(o.path().field("address"), "'" + text + "' is not an address (write host or host:port): "
                        + e.getMessage());
                return Optional.empty();
            }
        }).orElse(null);
        Reconnect reconnect = o.object("reconnect").map(this::reconnect).orElse(Reconnect.DEFAULTS);
        Record params = provider == null ? null
                : ParamsBinder.bind(o.node().get("params"), provider.paramsType(), path.field("params"), errors, baseDir)
                        .orElse(null);
        Driver made = null;
        if (provider != null && address != null && params != null) {
            try {
                made = make(provider, address, params);
            } catch (RuntimeException e) {
                errors.add(path, "driver '" + provider.name() + "' cannot be made: " + e.getMessage());
            }
        }
        return new InterfaceEntry(path, id, provider == null ? null : provider.name(), address, params, reconnect, made);
    }

    MethodEntry method(JsonNode node, JsonPath path) {
        Optional<CheckedObject> read = CheckedObject.of(node, path, errors);
        if (read.isEmpty()) {
            return new MethodEntry(path, null, null, null, Set.of(), Map.of(), Map.of(), null, false, Optional.empty(),
                    Optional.empty(), Fallback.NONE, null, Map.of(), ThreadChoice.AUTO);
        }
        CheckedObject o = read.get();
        o.allowOnly(ConfigLoader.METHOD_KEYS);
        String id = id(o);
        MethodProvider<?> provider = o.requiredString("type").flatMap(name -> {
            Optional<MethodProvider<?>> p = registry.method(name);
            if (p.isEmpty()) {
                errors.add(o.path().field("type"), "unknown method type '" + name + "' (known: "
                        + known(registry.methods()) + ")" + pluginsNote(registry));
            }
            return p;
        }).orElse(null);
        Layer layer = o.requiredString("layer").flatMap(name -> {
            try {
                return Optional.of(Layer.fromConfig(name));
            } catch (IllegalArgumentException e) {
                errors.add(o.path().field("layer"), e.getMessage());
                return Optional.empty();
            }
        }).orElse(null);
        boolean placeable = provider != null && layer != null && provider.layers().contains(layer);
        if (provider != null && layer != null && !placeable) {
            errors.add(o.path().field("layer"), "type '" + provider.name() + "' cannot be placed in the "
                    + layer.configName() + " layer (it belongs in: " + provider.layers().stream()
                    .map(Layer::configName).sorted().collect(Collectors.joining(", ")) + ")");
        }
        Record params = provider == null ? null
                : ParamsBinder.bind(o.node().get("params"), provider.paramsType(), path.field("params"), errors, baseDir)
                        .orElse(null);
        Ports ports = null;
        if (placeable && params != null) {
            try {
                ports = ports(provider, layer, params);
            } catch (RuntimeException | LinkageError e) {
                errors.add(path, "type '" + provider.name() + "' cannot list its ports for these params: "
                        + e.getMessage());
            }
        }
        Map<String, Source> inputs = new LinkedHashMap<>();
        o.strings("inputs").forEach((input, text) -> {
            try {
                inputs.put(input, SourceSyntax.source(text));
            } catch (IllegalArgumentException e) {
                errors.add(path.field("inputs").field(input), e.getMessage());
            }
        });
        Map<String, ChannelRef> commands = new LinkedHashMap<>();
        o.strings("commands").forEach((output, text) -> {
            try {
                commands.put(output, SourceSyntax.commandTarget(text));
            } catch (IllegalArgumentException e) {
                errors.add(path.field("commands").field(output), e.getMessage());
            }
        });
        Optional<Expose> expose = o.object("expose").flatMap(e -> expose(e, id));
        Optional<String> host = o.optionalString("host").filter(h -> workerHost(h, o.path().field("host")));
        Fallback fallback = fallback(o);
        Set<String> inputKeys = new LinkedHashSet<>();
        if (o.node().get("inputs") != null) {
            o.node().get("inputs").fieldNames().forEachRemaining(inputKeys::add);
        }
        return new MethodEntry(path, id, provider == null ? null : provider.name(), layer, inputKeys, inputs,
                commands, params, o.has("expose"), expose, host, fallback, ports, feedback(o), thread(o));
    }

    private ThreadChoice thread(CheckedObject o) {
        Optional<String> text = o.optionalString("thread");
        if (text.isEmpty()) {
            return ThreadChoice.AUTO;
        }
        try {
            return ThreadChoice.fromConfig(text.get());
        } catch (IllegalArgumentException e) {
            errors.add(o.path().field("thread"), e.getMessage());
            return ThreadChoice.AUTO;
        }
    }

    /** The {@code feedback} array: input names, each with the path it is declared at. */
    private Map<String, JsonPath> feedback(CheckedObject o) {
        Map<String, JsonPath> out = new LinkedHashMap<>();
        List<JsonNode> names = o.array("feedback");
        for (int i = 0; i < names.size(); i++) {
            JsonPath at = o.path().field("feedback").index(i);
            JsonNode n = names.get(i);
            if (!n.isTextual()) {
                errors.add(at, "must be a string (an input name), not " + CheckedObject.describe(n));
            } else if (out.containsKey(n.textValue())) {
                errors.add(at, "'" + n.textValue() + "' is listed twice: already at " + out.get(n.textValue()));
            } else {
                out.put(n.textValue(), at);
            }
        }
        return out;
    }

    private String id(CheckedObject o) {
        return o.requiredString("id").filter(id -> {
            if (SourceSyntax.ID.matcher(id).matches()) {
                return true;
            }
            errors.add(o.path().field("id"), "'" + id + "' is not an id: " + SourceSyntax.ID_RULE);
            return false;
        }).orElse(null);
    }

    /** An interface's or a bridge's {@code reconnect} object. */
    Reconnect reconnect(CheckedObject o) {
        o.allowOnly(ConfigLoader.RECONNECT_KEYS);
        Reconnect d = Reconnect.DEFAULTS;
        long initial = o.integer("initialMs", d.initialMs(), 1, ConfigLoader.MAX_MS);
        long max = o.integer("maxMs", d.maxMs(), 1, ConfigLoader.MAX_MS);
        if (max < initial) {
            errors.add(o.path().field("maxMs"), "must not be less than initialMs (" + initial + "), was " + max);
        }
        Reconnect.TcpKeepAlive k = d.tcpKeepAlive();
        return new Reconnect(initial, Math.max(initial, max),
                o.integer("connectTimeoutMs", d.connectTimeoutMs(), 1, ConfigLoader.MAX_MS),
                o.integer("readTimeoutMs", d.readTimeoutMs(), 0, ConfigLoader.MAX_MS),
                new Reconnect.TcpKeepAlive(
                        (int) o.integer("tcpKeepAliveIdleS", k.idleS(), 1, ConfigLoader.MAX_TCP_KEEPALIVE_S),
                        (int) o.integer("tcpKeepAliveIntervalS", k.intervalS(), 1, ConfigLoader.MAX_TCP_KEEPALIVE_S),
                        (int) o.integer("tcpKeepAliveCount", k.count(), 1, ConfigLoader.MAX_TCP_KEEPALIVE_COUNT)));
    }

    private Optional<Expose> expose(CheckedObject o, String methodId) {
        o.allowOnly(ConfigLoader.EXPOSE_KEYS);
        if (!o.has("port")) {
            errors.add(o.path().field("port"), "required key 'port' is missing");
        }
        long port = o.integer("port", -1, 1, 65_535);
        Optional<String> name = o.optionalString("name").filter(n -> {
            if (SourceSyntax.ID.matcher(n).matches()) {
                return true;
            }
            errors.add(o.path().field("name"), "'" + n + "' is not a socket name: " + SourceSyntax.ID_RULE);
            return false;
        });
        String bind = o.optionalString("bind").orElse(StatusConfig.DEFAULTS.bind());
        String socketName = o.has("name") ? name.orElse(null) : methodId;
        if (port < 0 || socketName == null) {
            return Optional.empty();
        }
        boolean tls = o.bool("tls", false);
        return Optional.of(new Expose(socketName, bind, (int) port, tls));
    }

    private Fallback fallback(CheckedObject o) {
        Optional<String> text = o.optionalString("fallback");
        if (text.isEmpty()) {
            return Fallback.NONE;
        }
        if (!o.has("host")) {
            errors.add(o.path().field("fallback"), "a fallback needs a \"host\": it says what to do while that worker is lost");
            return Fallback.NONE;
        }
        try {
            return Fallback.fromConfig(text.get());
        } catch (IllegalArgumentException e) {
            errors.add(o.path().field("fallback"), e.getMessage());
            return Fallback.NONE;
        }
    }

    private boolean workerHost(String text, JsonPath path) {
        try {
            InterfaceAddress a = InterfaceAddress.parse(text);
            if (a.port().isPresent()) {
                return true;
            }
            errors.add(path, "'" + text + "' names no port: write host:port");
        } catch (IllegalArgumentException e) {
            errors.add(path, "'" + text + "' is not host:port: " + e.getMessage());
        }
        return false;
    }

    private static <P extends Record> Ports ports(MethodProvider<P> provider, Layer layer, Record params) {
        return provider.ports(layer, provider.paramsType().cast(params));
    }

    private static <P extends Record> Driver make(DriverProvider<P> provider, InterfaceAddress address, Record params) {
        return provider.create(address, provider.paramsType().cast(params));
    }

    private static String known(Map<String, ?> table) {
        return table.isEmpty() ? "none registered" : String.join(", ", table.keySet());
    }

    /** What the plugins gave, for an error about a type nobody registered: "; plugins: ..." or nothing. */
    static String pluginsNote(PluginRegistry registry) {
        String why = registry.report().why();
        return why.isEmpty() ? "" : "; " + why;
    }
}
