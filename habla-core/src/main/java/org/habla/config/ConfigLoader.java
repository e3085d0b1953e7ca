package org.habla.config;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import org.habla.net.Limits;
import org.habla.plugin.PluginRegistry;

/**
 * Reads a config file into a {@link HablaConfig}, strictly: unknown keys, wrong types, out-of-range
 * numbers, unknown types, bad params, dangling references, duplicate ports and layer violations all come
 * back together in one {@link ConfigException}, each error at its JSON path. See {@code docs/config.md}.
 */
public final class ConfigLoader {

    static final Set<String> ROOT_KEYS =
            Set.of("$schema", "description", "system", "limits", "safety", "status", "interfaces", "methods", "bridges",
                    "security");
    static final Set<String> LIMITS_KEYS =
            Set.of("maxLineBytes", "maxBinaryBytes", "maxClientsPerPort", "clientQueueSamples", "maxPendingPerPort", "idleTimeoutMs",
                    "frameTimeoutMs", "evictableIdleMs", "socketBlockBudgetBytes", "processBlockBudgetBytes");
    static final Set<String> SAFETY_KEYS = Set.of("watchdogMs");
    static final Set<String> STATUS_KEYS = Set.of("bind", "port", "monitorPort", "monitorBind", "tls");
    static final Set<String> INTERFACE_KEYS = Set.of("id", "driver", "address", "params", "reconnect");
    static final Set<String> RECONNECT_KEYS = Set.of("initialMs", "maxMs", "connectTimeoutMs", "readTimeoutMs",
            "tcpKeepAliveIdleS", "tcpKeepAliveIntervalS", "tcpKeepAliveCount");
    static final Set<String> METHOD_KEYS =
            Set.of("id", "type", "layer", "inputs", "commands", "params", "expose", "host", "fallback", "feedback",
                    "thread");
    static final Set<String> EXPOSE_KEYS = Set.of("port", "name", "bind", "tls");
    static final Set<String> BRIDGE_KEYS = Set.of("id", "type", "address", "params", "reconnect");

    /** The keys of each fixed object of the format, by where it sits ({@code []} stands for any element). */
    static final Map<String, Set<String>> KEYS_BY_OBJECT = Map.ofEntries(
            Map.entry("$", ROOT_KEYS),
            Map.entry("$.limits", LIMITS_KEYS),
            Map.entry("$.safety", SAFETY_KEYS),
            Map.entry("$.status", STATUS_KEYS),
            Map.entry("$.interfaces[]", INTERFACE_KEYS),
            Map.entry("$.interfaces[].reconnect", RECONNECT_KEYS),
            Map.entry("$.methods[]", METHOD_KEYS),
            Map.entry("$.methods[].expose", EXPOSE_KEYS),
            Map.entry("$.bridges[]", BRIDGE_KEYS),
            Map.entry("$.bridges[].reconnect", RECONNECT_KEYS),
            Map.entry("$.security", SecurityReader.SECURITY_KEYS),
            Map.entry("$.security.tls", SecurityReader.TLS_KEYS));

    /** The largest JSON line a socket may be allowed: 16 MiB. */
    static final int MAX_LINE_BYTES = 16 * 1024 * 1024;
    /** The largest binary block a socket may be allowed: 256 MiB. */
    static final int MAX_BINARY_BYTES = 256 * 1024 * 1024;
    /** The most clients one port may be allowed. */
    static final int MAX_CLIENTS_PER_PORT = 1_024;
    /** The most connections without a request one port may be allowed. */
    static final int MAX_PENDING_PER_PORT = 65_536;
    /** The longest queue for one client. */
    static final int MAX_CLIENT_QUEUE_SAMPLES = 65_536;
    /** The longest time setting (watchdog, back-off, time-outs): one hour. */
    static final long MAX_MS = 3_600_000;
    /** The longest TCP keep-alive idle time or probe interval a config may ask for [s]. */
    static final long MAX_TCP_KEEPALIVE_S = 3_600;
    /** The most unanswered TCP keep-alive probes a config may allow. */
    static final long MAX_TCP_KEEPALIVE_COUNT = 100;
    /** The largest memory a port's or the process's blocks in flight may be allowed: 4 GiB. */
    static final long MAX_BLOCK_BUDGET_BYTES = 4L * 1024 * 1024 * 1024;

    private static final ObjectMapper JSON = JsonMapper.builder()
            .enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION)
            .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
            .build();

    private final PluginRegistry registry;

    private Path baseDir = Path.of("").toAbsolutePath();

    public ConfigLoader(PluginRegistry registry) {
        this.registry = Objects.requireNonNull(registry, "registry");
    }

    /**
     * Reads a config of nothing but a system name and binds an empty params object, and drops both: Jackson's
     * readers are made and its classes loaded. {@code habla run} does this on a thread of its own while the command
     * line is being read, so that loading the real config starts warm (docs/performance.md (l)).
     */
    public static void preload() {
        try {
            new ConfigLoader(PluginRegistry.of(List.of(), List.of())).parse("{\"system\": \"preload\"}");
        } catch (ConfigException e) {
            throw new IllegalStateException("the preload config is not valid: " + e.errors(), e);
        }
        ParamsBinder.bind(null, org.habla.plugin.NoParams.class, JsonPath.ROOT, new ConfigErrors());
    }

    /** Reads and checks a config file; I/O errors become an error at {@code $}. */
    public HablaConfig load(Path file) throws ConfigException {
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder().decode(java.nio.ByteBuffer.wrap(Files.readAllBytes(file)))
                    .toString();
        } catch (CharacterCodingException e) {
            throw new ConfigException(List.of(new ConfigError("$", "cannot read " + file + ": not UTF-8 text")));
        } catch (NoSuchFileException e) {
            throw new ConfigException(List.of(new ConfigError("$", "cannot read " + file + ": no such file")));
        } catch (IOException e) {
            throw new ConfigException(List.of(new ConfigError("$", "cannot read " + file + ": " + e)));
        }
        Path dir = file.toAbsolutePath().getParent();
        return parse(text, dir == null ? Path.of("").toAbsolutePath() : dir);
    }

    /** Reads and checks a config given as JSON text; relative file params are taken from the working folder. */
    public HablaConfig parse(String json) throws ConfigException {
        return parse(json, Path.of("").toAbsolutePath());
    }

    /** Reads and checks a config given as JSON text; relative file params are taken from {@code baseDir}. */
    public HablaConfig parse(String json, Path baseDir) throws ConfigException {
        this.baseDir = baseDir;
        JsonNode root;
        try {
            root = JSON.readTree(json);
        } catch (JsonProcessingException e) {
            JsonLocation at = e.getLocation();
            String where = at == null ? "" : " at line " + at.getLineNr() + ", column " + at.getColumnNr();
            throw new ConfigException(List.of(new ConfigError("$", "invalid JSON" + where + ": " + e.getOriginalMessage())));
        }
        ConfigErrors errors = new ConfigErrors();
        Optional<HablaConfig> config = read(root, errors);
        if (!errors.isEmpty() || config.isEmpty()) {
            throw new ConfigException(errors.sorted());
        }
        return config.get();
    }

    private Optional<HablaConfig> read(JsonNode node, ConfigErrors errors) {
        if (node == null || node.isMissingNode()) {
            errors.add(JsonPath.ROOT, "the config is empty: it must be a JSON object");
            return Optional.empty();
        }
        Optional<CheckedObject> read = CheckedObject.of(node, JsonPath.ROOT, errors);
        if (read.isEmpty()) {
            return Optional.empty();
        }
        CheckedObject root = read.get();
        root.allowOnly(ROOT_KEYS);
        root.optionalString("$schema");
        root.optionalString("description");
        Optional<String> system = root.requiredString("system");
        Limits limits = root.object("limits").map(o -> limits(o, errors)).orElse(Limits.DEFAULTS);
        Safety safety = root.object("safety").map(this::safety).orElse(Safety.DEFAULTS);
        StatusConfig status = root.object("status").map(this::status).orElse(StatusConfig.DEFAULTS);

        EntryReader entries = new EntryReader(registry, errors, baseDir);
        List<InterfaceEntry> interfaces = new ArrayList<>();
        List<JsonNode> interfaceNodes = root.array("interfaces");
        for (int i = 0; i < interfaceNodes.size(); i++) {
            interfaces.add(entries.iface(interfaceNodes.get(i), JsonPath.ROOT.field("interfaces").index(i)));
        }
        List<MethodEntry> methods = new ArrayList<>();
        List<JsonNode> methodNodes = root.array("methods");
        for (int i = 0; i < methodNodes.size(); i++) {
            methods.add(entries.method(methodNodes.get(i), JsonPath.ROOT.field("methods").index(i)));
        }
        new DuplicateCheck(errors).run(status, root.has("status"), interfaces, methods);
        new WiringCheck(errors, interfaces, methods).run(methods);
        java.util.Set<String> sockets = new java.util.HashSet<>();
        methods.forEach(m -> m.expose().ifPresent(x -> sockets.add(x.name())));
        List<BridgeConfig> bridges = new BridgeReader(registry, errors, baseDir).read(root.array("bridges"), sockets);
        SecurityReader securityReader = new SecurityReader(errors, baseDir);
        SecurityConfig security = securityReader.read(root.object("security"), sockets);
        securityReader.checkPolicy(security, status, methods);
        if (security.credentials() != null) {
            checkBridgeRoles(root.array("bridges"), bridges, security, errors);
        }

        if (!errors.isEmpty() || system.isEmpty()
                || !interfaces.stream().allMatch(InterfaceEntry::complete)
                || !methods.stream().allMatch(MethodEntry::complete)) {
            return Optional.empty();
        }
        return Optional.of(new HablaConfig(system.get(), limits, safety, status,
                interfaces.stream().map(InterfaceEntry::toConfig).toList(),
                methods.stream().map(MethodEntry::toConfig).toList(), bridges, security));
    }

    /** With a credentials file, a bridge may take actions only for the sockets the file gives it. */
    private void checkBridgeRoles(List<JsonNode> nodes, List<BridgeConfig> bridges, SecurityConfig security,
            ConfigErrors errors) {
        for (BridgeConfig b : bridges) {
            int index = -1;
            for (int i = 0; i < nodes.size(); i++) {
                if (b.id().equals(nodes.get(i).path("id").asText())) {
                    index = i;
                }
            }
            Set<String> actions = new java.util.TreeSet<>(actions(b));
            actions.removeAll(security.credentials().bridgeCommands(b.id()));
            if (!actions.isEmpty() && index >= 0) {
                errors.add(JsonPath.ROOT.field("bridges").index(index), "bridge '" + b.id() + "' takes actions for "
                        + actions + ", which the credentials file does not give it: add \"bridges\": {\"" + b.id()
                        + "\": {\"" + actions.iterator().next() + "\": \"command\"}} to "
                        + security.credentialsFile().getFileName());
            }
        }
    }

    @SuppressWarnings("unchecked")
    private <P extends Record> Set<String> actions(BridgeConfig b) {
        var provider = (org.habla.plugin.BridgeProvider<P>) registry.bridge(b.type()).orElseThrow();
        return provider.actionSockets((P) b.params());
    }

    private Limits limits(CheckedObject o, ConfigErrors errors) {
        o.allowOnly(LIMITS_KEYS);
        Limits d = Limits.DEFAULTS;
        int maxBinaryBytes = (int) o.integer("maxBinaryBytes", d.maxBinaryBytes(), 1, MAX_BINARY_BYTES);
        // Budgets left out grow with a larger maxBinaryBytes, so that raising it alone stays valid.
        long socketBudget = o.integer("socketBlockBudgetBytes", Math.max(d.socketBlockBudgetBytes(), maxBinaryBytes),
                1, MAX_BLOCK_BUDGET_BYTES);
        Limits l = new Limits(
                (int) o.integer("maxLineBytes", d.maxLineBytes(), 1, MAX_LINE_BYTES),
                maxBinaryBytes,
                (int) o.integer("maxClientsPerPort", d.maxClientsPerPort(), 1, MAX_CLIENTS_PER_PORT),
                (int) o.integer("clientQueueSamples", d.clientQueueSamples(), 1, MAX_CLIENT_QUEUE_SAMPLES),
                (int) o.integer("maxPendingPerPort", d.maxPendingPerPort(), 1, MAX_PENDING_PER_PORT),
                o.integer("idleTimeoutMs", d.idleTimeoutMs(), 0, MAX_MS),
                o.integer("frameTimeoutMs", d.frameTimeoutMs(), 1, MAX_MS),
                o.integer("evictableIdleMs", d.evictableIdleMs(), 0, MAX_MS),
                socketBudget,
                o.integer("processBlockBudgetBytes", Math.max(d.processBlockBudgetBytes(), socketBudget),
                        1, MAX_BLOCK_BUDGET_BYTES));
        if (l.socketBlockBudgetBytes() < l.maxBinaryBytes()) {
            errors.add(o.path().field("socketBlockBudgetBytes"), "must not be less than maxBinaryBytes ("
                    + l.maxBinaryBytes() + "), or the largest block could never be taken; was " + l.socketBlockBudgetBytes());
        } else if (l.processBlockBudgetBytes() < l.socketBlockBudgetBytes()) {
            errors.add(o.path().field("processBlockBudgetBytes"), "must not be less than socketBlockBudgetBytes ("
                    + l.socketBlockBudgetBytes() + "), was " + l.processBlockBudgetBytes());
        }
        return l;
    }

    private Safety safety(CheckedObject o) {
        o.allowOnly(SAFETY_KEYS);
        return new Safety(o.integer("watchdogMs", Safety.DEFAULTS.watchdogMs(), 0, MAX_MS));
    }

    private StatusConfig status(CheckedObject o) {
        o.allowOnly(STATUS_KEYS);
        StatusConfig d = StatusConfig.DEFAULTS;
        return new StatusConfig(o.optionalString("bind").orElse(d.bind()),
                (int) o.integer("port", d.port(), 0, 65_535), (int) o.integer("monitorPort", d.monitorPort(), 0, 65_535),
                o.bool("tls", false), o.optionalString("monitorBind").orElse(d.monitorBind()));
    }
}
