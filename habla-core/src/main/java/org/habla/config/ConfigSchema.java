package org.habla.config;

import static org.habla.config.SchemaNodes.bool;
import static org.habla.config.SchemaNodes.integer;
import static org.habla.config.SchemaNodes.object;
import static org.habla.config.SchemaNodes.props;
import static org.habla.config.SchemaNodes.ref;
import static org.habla.config.SchemaNodes.sortKeys;
import static org.habla.config.SchemaNodes.string;
import static org.habla.config.SchemaNodes.strings;
import static org.habla.config.SchemaNodes.when;
import static org.habla.config.SchemaNodes.withRequired;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.habla.method.Layer;
import org.habla.net.Limits;
import org.habla.plugin.DriverProvider;
import org.habla.plugin.MethodProvider;
import org.habla.plugin.PluginRegistry;

/**
 * The JSON Schema (draft 2020-12) of HABLA config files, for editors: the fixed structure with its
 * types, ranges, defaults and descriptions, and for each registered method type and driver type its
 * params object, selected with {@code if}/{@code then} on {@code type} or {@code driver}. The output
 * depends only on the registry: every {@code properties} and {@code $defs} object is sorted by key.
 */
public final class ConfigSchema {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
    private static final String ID_PATTERN = "^" + SourceSyntax.ID.pattern() + "$";
    private static final String NAME = "[A-Za-z][A-Za-z0-9_-]{0,63}";

    private ConfigSchema() {
    }

    /** The schema for every type in {@code registry}. */
    public static ObjectNode generate(PluginRegistry registry) {
        ObjectNode root = NODES.objectNode();
        root.put("$schema", "https://json-schema.org/draft/2020-12/schema");
        root.put("$id", "habla-config.schema.json");
        root.put("title", "HABLA config");
        root.put("description", "A HABLA daemon config: the robot's interfaces, the three-layer method graph and "
                + "the daemon's settings. Checked strictly by `habla check`; see docs/config.md.");
        root.put("type", "object");
        root.put("additionalProperties", false);
        root.putArray("required").add("system");
        ObjectNode p = root.putObject("properties");
        p.set("$schema", string("The schema this file follows; ignored by HABLA."));
        p.set("description", string("Free text about the config; ignored by HABLA."));
        p.set("system", string("The name of the robot or system this config drives.").put("minLength", 1));
        p.set("limits", limits());
        p.set("safety", object("The motion watchdog.")
                .set("properties", props("watchdogMs", integer(0, ConfigLoader.MAX_MS, Safety.DEFAULTS.watchdogMs(),
                        "Stop the robot when no control client has written for this long; 0 turns the silence check off [ms]"))));
        p.set("status", object("The status endpoint read by `habla status`.").set("properties", props(
                "bind", string("The address the status endpoint listens on (0.0.0.0: every IPv4 address; ::, both "
                        + "families).").put("default", StatusConfig.DEFAULTS.bind()),
                "port", integer(0, 65_535, StatusConfig.DEFAULTS.port(), "The TCP port; 0 turns the endpoint off."),
                "monitorPort", integer(0, 65_535, StatusConfig.DEFAULTS.monitorPort(),
                        "The live monitor's port: a web page and the Foxglove WebSocket protocol; 0: no monitor."),
                "monitorBind", string("The address the monitor listens on; it has no authentication, so beyond "
                        + "loopback it needs security.insecure.").put("default", StatusConfig.DEFAULTS.monitorBind()),
                "tls", bool(false, "The status endpoint speaks TLS with the certificate of security.tls."))));
        p.set("interfaces", NODES.objectNode().put("description", "The robot's interface servers.")
                .put("type", "array").set("items", ref("interface")));
        p.set("methods", NODES.objectNode().put("description", "The methods of the graph.")
                .put("type", "array").set("items", ref("method")));
        p.set("bridges", NODES.objectNode().put("description", "Bridges that carry exposed methods to another "
                + "transport (an MQTT broker) beside their sockets.").put("type", "array").set("items", bridge(registry)));

        p.set("security", security());

        ObjectNode defs = root.putObject("$defs");
        defs.set("id", string("A letter, then up to 63 letters, digits, '_' or '-'.").put("pattern", ID_PATTERN));
        defs.set("source", string("Where an input's samples come from: \"methodId.output\", "
                + "\"@interfaceId.channel\" (sensors_actuators layer) or \"control\" (virtual layer).")
                .put("pattern", "^(control|@?" + NAME + "\\." + NAME + ")$"));
        defs.set("channel", string("An interface channel: \"@interfaceId.channel\".")
                .put("pattern", "^@" + NAME + "\\." + NAME + "$"));
        defs.set("interface", iface(registry));
        defs.set("method", method(registry));
        registry.methods().forEach((name, provider) -> defs.set("params.method." + name, params(provider)));
        registry.drivers().forEach((name, provider) -> defs.set("params.driver." + name, params(provider)));
        registry.bridges().forEach((name, provider) -> defs.set("params.bridge." + name,
                ParamsSchema.of(provider.paramsType()).put("description", provider.description())));
        sortKeys(root);
        return root;
    }

    /** The schema as pretty-printed JSON text ending with a newline. */
    public static String text(PluginRegistry registry) {
        try {
            return JSON.writeValueAsString(generate(registry)).replace("\r\n", "\n") + "\n";
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("the schema cannot be written", e);
        }
    }

    private static ObjectNode security() {
        return object("Who may use the daemon's ports: credentials, the audit log, TLS (docs/security.md).")
                .set("properties", props(
                        "credentials", string("The credentials file, beside the config: named clients, their tokens "
                                + "and roles per socket, the worker secret. Readable by its owner only."),
                        "auditLog", string("The append-only audit log of every accepted and refused command; "
                                + "with credentials it defaults to " + SecurityReader.DEFAULT_AUDIT_LOG
                                + " beside the config."),
                        "insecure", bool(false, "Allow ports beyond loopback without authentication (a warning at "
                                + "every start)."),
                        "loopback", string("Whether ports bound to loopback are open or require authentication too.")
                                .put("default", "open").set("enum", strings("open", "authenticated")),
                        "tls", withRequired(object("The certificate and key of TLS sockets (\"tls\": true)."),
                                "certificate", "key").set("properties", props(
                                        "certificate", string("The PEM certificate (chain)."),
                                        "key", string("Its unencrypted PKCS#8 PEM key, readable by its owner only."))),
                        "workerTrust", string("The PEM certificate workers must present: the worker link speaks "
                                + "TLS.")));
    }

    private static ObjectNode limits() {
        Limits d = Limits.DEFAULTS;
        return object("The limits every socket enforces.").set("properties", props(
                "maxLineBytes", integer(1, ConfigLoader.MAX_LINE_BYTES, d.maxLineBytes(),
                        "The longest JSON line accepted, newline excluded [bytes]"),
                "maxBinaryBytes", integer(1, ConfigLoader.MAX_BINARY_BYTES, d.maxBinaryBytes(),
                        "The largest \"bytes\" block accepted after a line [bytes]"),
                "maxClientsPerPort", integer(1, ConfigLoader.MAX_CLIENTS_PER_PORT, d.maxClientsPerPort(),
                        "Clients (connections admitted: a first request or, where the port requires it, an authentication) at once on one port"),
                "maxPendingPerPort", integer(1, ConfigLoader.MAX_PENDING_PER_PORT, d.maxPendingPerPort(),
                        "Connections at once on one port not admitted yet; of the address with the most of them, the "
                                + "one waiting longest gives way to a newcomer"),
                "clientQueueSamples", integer(1, ConfigLoader.MAX_CLIENT_QUEUE_SAMPLES, d.clientQueueSamples(),
                        "Samples waiting for one slow client before the oldest are dropped"),
                "idleTimeoutMs", integer(0, ConfigLoader.MAX_MS, d.idleTimeoutMs(),
                        "Close a connection that has taken nothing of the lines waiting for it and sent nothing for this "
                                + "long, or has not authenticated within it (a reader is never idle); 0: never [ms]"),
                "frameTimeoutMs", integer(1, ConfigLoader.MAX_MS, d.frameTimeoutMs(),
                        "A frame a peer has begun to send must arrive whole within this time; the status "
                                + "endpoint's answer must be taken within it [ms]"),
                "evictableIdleMs", integer(0, ConfigLoader.MAX_MS, d.evictableIdleMs(),
                        "On a full port, a client idle this long may be evicted to admit a newcomer [ms]"),
                "socketBlockBudgetBytes", integer(1, ConfigLoader.MAX_BLOCK_BUDGET_BYTES, d.socketBlockBudgetBytes(),
                        "Memory for \"bytes\" blocks in flight on one port, all its connections together; "
                                + "not below maxBinaryBytes (when left out: at least maxBinaryBytes) [bytes]"),
                "processBlockBudgetBytes", integer(1, ConfigLoader.MAX_BLOCK_BUDGET_BYTES, d.processBlockBudgetBytes(),
                        "Memory for blocks in flight on every port of the process together; not below "
                                + "socketBlockBudgetBytes [bytes]")));
    }

    /** An interface's or a bridge's {@code reconnect} object. */
    private static ObjectNode reconnect(String description) {
        Reconnect d = Reconnect.DEFAULTS;
        return object(description).set("properties", props(
                "initialMs", integer(1, ConfigLoader.MAX_MS, d.initialMs(),
                        "The first wait after a failure, and the wait after a refused connect [ms]"),
                "maxMs", integer(1, ConfigLoader.MAX_MS, d.maxMs(), "The longest wait; not below initialMs [ms]"),
                "connectTimeoutMs", integer(1, ConfigLoader.MAX_MS, d.connectTimeoutMs(),
                        "How long one connect and handshake may take [ms]"),
                "readTimeoutMs", integer(0, ConfigLoader.MAX_MS, d.readTimeoutMs(),
                        "Silence after which a connection whose peer keeps sending is declared lost, "
                        + "replacing the driver's limit; 0 keeps the driver's; quiet connections ignore it [ms]"),
                "tcpKeepAliveIdleS", integer(1, ConfigLoader.MAX_TCP_KEEPALIVE_S, d.tcpKeepAlive().idleS(),
                        "Idle time before the first TCP keep-alive probe [s]"),
                "tcpKeepAliveIntervalS", integer(1, ConfigLoader.MAX_TCP_KEEPALIVE_S,
                        d.tcpKeepAlive().intervalS(), "Time between TCP keep-alive probes [s]"),
                "tcpKeepAliveCount", integer(1, ConfigLoader.MAX_TCP_KEEPALIVE_COUNT, d.tcpKeepAlive().count(),
                        "Unanswered TCP keep-alive probes after which the connection fails")));
    }

    private static ObjectNode iface(PluginRegistry registry) {
        ObjectNode s = withRequired(object("One robot interface: a driver type, where the robot's servers are, "
                + "the driver's params."), "id", "driver", "address");
        s.set("properties", props(
                "id", ref("id").put("description", "The id used in channel references (\"@id.channel\")."),
                "driver", string("The driver type.").set("enum", strings(registry.drivers().keySet())),
                "address", string("host or host:port of the robot's main server.").put("minLength", 1),
                "params", object("The driver's own params (see the driver type).").put("additionalProperties", true),
                "reconnect", reconnect("How the link notices a lost peer and is re-established.")));
        ArrayNode cases = s.putArray("allOf");
        registry.drivers().keySet().forEach(name -> cases.add(when("driver", name,
                props("params", ref("params.driver." + name)))));
        return s;
    }

    private static ObjectNode bridge(PluginRegistry registry) {
        ObjectNode s = withRequired(object("One bridge: a bridge type, where it connects, its params."), "id", "type",
                "address");
        s.set("properties", props(
                "id", ref("id").put("description", "The bridge's id, for logs and the status."),
                "type", string("The bridge type.").set("enum", strings(registry.bridges().keySet())),
                "address", string("host or host:port of the broker.").put("minLength", 1),
                "params", object("The bridge's own params (see the bridge type).").put("additionalProperties", true),
                "reconnect", reconnect("How the bridge's lost connection is re-established (the back-off and the "
                        + "connect time-out; the client library keeps its own keep-alive).")));
        ArrayNode cases = s.putArray("allOf");
        registry.bridges().keySet().forEach(name -> cases.add(when("type", name,
                props("params", ref("params.bridge." + name)))));
        return s;
    }

    private static ObjectNode method(PluginRegistry registry) {
        ObjectNode s = withRequired(object("One method of the three-layer graph."), "id", "type", "layer");
        ArrayNode layers = NODES.arrayNode();
        for (Layer l : Layer.values()) {
            layers.add(l.configName());
        }
        s.set("properties", props(
                "id", ref("id").put("description", "The id used in references (\"id.output\")."),
                "type", string("The method type.").set("enum", strings(registry.methods().keySet())),
                "layer", string("The layer the method is placed in.").set("enum", layers),
                "inputs", object("Input name -> source.").set("additionalProperties", ref("source")),
                "commands", object("Output name -> interface command channel (sensors_actuators layer only).")
                        .set("additionalProperties", ref("channel")),
                "params", object("The type's own params (see the method type).").put("additionalProperties", true),
                "expose", withRequired(object("The method's control socket (virtual layer only)."), "port")
                        .set("properties", props(
                                "port", integer(1, 65_535, "The TCP port; unique in the config."),
                                "name", ref("id").put("description", "The socket's name; defaults to the method id."),
                                "bind", string("The address to listen on; beyond loopback it needs "
                                        + "security.credentials or security.insecure.").put("default", "127.0.0.1"),
                                "tls", bool(false, "Speak TLS with the certificate of security.tls."))),
                "host", string("The worker that runs the method, host:port; absent means the daemon itself.")
                        .put("pattern", "^.+:[0-9]{1,5}$"),
                "fallback", string("What the daemon does while the method's worker is lost: none (its outputs are "
                        + "stale) or local (the daemon runs it meanwhile). Only with host.")
                        .put("default", "none").set("enum", strings("none", "local")),
                "feedback", NODES.objectNode().put("type", "array").put("uniqueItems", true)
                        .put("description", "Inputs of this method whose wires close a wiring cycle on purpose; every"
                                + " wire on a declared cycle delivers only the latest sample.")
                        .set("items", string("An input name.")),
                "thread", string("auto: a light method fed from one thread runs on that thread, with no queue "
                        + "between; own: a thread of its own whatever its type.")
                        .put("default", "auto").set("enum", strings("auto", "own"))));
        ArrayNode cases = s.putArray("allOf");
        registry.methods().forEach((name, provider) -> {
            ArrayNode typeLayers = NODES.arrayNode();
            provider.layers().stream().map(Layer::configName).sorted().forEach(typeLayers::add);
            cases.add(when("type", name, props("params", ref("params.method." + name),
                    "layer", NODES.objectNode().set("enum", typeLayers))));
        });
        return s;
    }

    private static ObjectNode params(MethodProvider<?> provider) {
        return ParamsSchema.of(provider.paramsType()).put("description", provider.description());
    }

    private static ObjectNode params(DriverProvider<?> provider) {
        return ParamsSchema.of(provider.paramsType()).put("description", provider.description());
    }
}
