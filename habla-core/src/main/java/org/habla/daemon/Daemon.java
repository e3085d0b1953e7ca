package org.habla.daemon;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.function.Consumer;
import java.util.stream.Collectors;
import org.habla.bridge.Bridge;
import org.habla.graph.BridgeLink;
import org.habla.config.BridgeConfig;
import org.habla.config.ConfigError;
import org.habla.config.HablaConfig;
import org.habla.config.MethodConfig;
import org.habla.config.Source;
import org.habla.driver.ChannelDescriptor;
import org.habla.graph.EngineClock;
import org.habla.graph.GraphTap;
import org.habla.graph.MethodGraph;
import org.habla.graph.RecordedSkips;
import org.habla.net.BlockBudget;
import org.habla.graph.OutputInfo;
import org.habla.sample.Sample;
import org.habla.net.ControlPoint;
import org.habla.net.ControlServer;
import org.habla.plugin.PluginRegistry;
import org.habla.status.StatusServer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The HABLA daemon: a config's method graph with a control server on every exposed method's port, the
 * config's bridges and the status endpoint, and the products that run beside it ({@link DaemonExtension}: the live
 * monitor). The one assembly point between the engine and the sockets.
 */
public final class Daemon implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(Daemon.class);
    /** How long a worker may take to say what it runs when the daemon starts. */
    private static final int WORKER_CHECK_MILLIS = 2_000;
    /** The name the live monitor runs under beside a daemon ({@link DaemonExtension.Running#name}). */
    public static final String MONITOR = "monitor";

    private final HablaConfig config;
    private final MethodGraph graph;
    private final EngineClock clock;
    private final Map<String, ControlServer> servers = new LinkedHashMap<>();
    /** Memory for blocks clients are sending, on every control socket together. */
    private final BlockBudget blockBudget;
    private final Map<String, BridgeLink> bridges = new LinkedHashMap<>();
    private StatusServer statusServer;
    private PortGuards guards;
    private final List<DaemonExtension.Running> extensions = new ArrayList<>();
    private volatile boolean closed;

    private Daemon(HablaConfig config, MethodGraph graph, EngineClock clock) {
        this.config = config;
        this.graph = graph;
        this.clock = clock;
        this.blockBudget = BlockBudget.of("limits.processBlockBudgetBytes", config.limits().processBlockBudgetBytes());
    }

    /**
     * Builds and starts everything; if a port cannot be bound, whatever was started is stopped again and the
     * exception says which port. A worker that cannot run a method placed on it stops the start with a {@link
     * PlacementRefusedException}.
     */
    public static Daemon start(HablaConfig config, PluginRegistry registry, EngineClock clock) throws IOException {
        return start(config, registry, clock, GraphTap.NONE);
    }

    /** Builds and starts everything with a tap that sees what crosses the graph's edges (a recording). */
    public static Daemon start(HablaConfig config, PluginRegistry registry, EngineClock clock, GraphTap tap)
            throws IOException {
        checkPlacements(config);
        return assemble(config, registry, MethodGraph.build(config, registry, clock, tap), clock, true);
    }

    /**
     * Builds and starts a daemon that replays a recording: the same control sockets, but every interface is
     * fed from the recording through {@link #graph()} instead of connecting to a robot, and every input skips
     * the samples the recorded run skipped ({@code skips}).
     */
    public static Daemon replaying(HablaConfig config, PluginRegistry registry, EngineClock clock, GraphTap tap,
            Map<String, List<ChannelDescriptor>> channels, RecordedSkips skips) throws IOException {
        checkPlacements(config);
        // A replay carries no bridge: what it computes again must not reach a broker as if it were live.
        MethodGraph graph = MethodGraph.replaying(config, registry, clock, tap, channels, skips);
        return assemble(config, registry, graph, clock, false);
    }

    /** Asks every worker the config places methods on whether it can run them. */
    private static void checkPlacements(HablaConfig config) throws PlacementRefusedException {
        List<String> refusals = WorkerCheck.refusals(config, WORKER_CHECK_MILLIS);
        if (!refusals.isEmpty()) {
            throw new PlacementRefusedException(refusals);
        }
    }

    /**
     * Checks that every port the config names can be listened on, without listening on any: a port that cannot be
     * had is a {@link PortsUnavailableException} naming it at its JSON path.
     */
    public static void checkPorts(HablaConfig config) throws PortsUnavailableException {
        List<ConfigError> taken = PortCheck.unavailable(config);
        if (!taken.isEmpty()) {
            throw new PortsUnavailableException(taken);
        }
    }

    /**
     * Binds every port first — the control sockets and the status endpoint — then starts the extensions (the monitor
     * binds its port), and only when all are held serves the control sockets and the status endpoint, then starts the
     * bridges (when {@code withBridges}), then the graph: a port that cannot be had stops the start first.
     */
    private static Daemon assemble(HablaConfig config, PluginRegistry registry, MethodGraph graph, EngineClock clock,
            boolean withBridges) throws IOException {
        try {
            checkPorts(config);
        } catch (PortsUnavailableException e) {
            graph.close();
            throw e;
        }
        Daemon d = new Daemon(config, graph, clock);
        try {
            d.guards = PortGuards.of(config);
            d.guards.audit().addListener(graph::audit);
            for (ControlPoint point : d.graph.controlPoints()) {
                ControlServer server = new ControlServer(point, d.graph.exposeOf(point), config.limits(),
                        d.blockBudget, d.guards.socket(d.graph.exposeOf(point)));
                d.servers.put(point.name(), server);
                try {
                    server.bind();
                } catch (IOException e) {
                    throw new PortsUnavailableException(List.of(PortCheck.controlSocketError(config, point.methodId(), e)));
                }
            }
            if (config.status().port() > 0) {
                d.statusServer = new StatusServer(config.status(), config.limits(), d::status,
                        d.guards.status(config.status()));
                try {
                    d.statusServer.bind();
                } catch (IOException e) {
                    throw new PortsUnavailableException(List.of(new ConfigError("$.status.port", e.getMessage())));
                }
            }
            // An extension binds and serves in one step: they start last of the ports, before any control socket
            // serves, so a port of theirs taken meanwhile still leaves the control sockets unused.
            LiveGraph view = d.liveView();
            for (DaemonExtension extension : ServiceLoader.load(DaemonExtension.class,
                    Thread.currentThread().getContextClassLoader())) {
                extension.start(config, registry, view).ifPresent(d.extensions::add);
            }
            if (config.status().monitorPort() > 0 && d.extensionPort(MONITOR) == 0) {
                LOG.warn("status.monitorPort is {}, but no monitor is on this class path (habla-monitor): none runs",
                        config.status().monitorPort());
            }
            for (ControlServer server : d.servers.values()) {
                server.start();
            }
            if (d.statusServer != null) {
                d.statusServer.start();
            }
            if (withBridges) {
                for (BridgeConfig bc : config.bridges()) {
                    Bridge bridge = Bridges.create(registry, bc);
                    bridge.start(config.system(), d.graph.controlPoints(),
                            Bridges.role(registry, bc).auditedIn(d.guards.audit()));
                    BridgeLink link = new BridgeLink(bc.id(), bridge, bc.reconnect());
                    d.bridges.put(bc.id(), link);
                    link.start();
                }
            }
            d.graph.start();
        } catch (IOException | RuntimeException e) {
            d.close();
            throw e;
        }
        LOG.info("HABLA daemon '{}' running: {} control sockets{}{}", config.system(), d.servers.size(),
                d.statusServer == null ? "" : ", status on port " + d.statusServer.port(),
                d.extensions.stream().map(e -> ", " + e.where()).collect(Collectors.joining()));
        return d;
    }

    /** The running graph (a replay pushes the recorded readings into it). */
    public MethodGraph graph() {
        return graph;
    }

    public HablaConfig config() {
        return config;
    }

    /** The bound port of the control socket {@code name} (useful when the config asked for port 0). */
    public int port(String name) {
        ControlServer s = servers.get(name);
        if (s == null) {
            throw new IllegalArgumentException("no control socket '" + name + "'");
        }
        return s.port();
    }

    /** The status endpoint's port, or 0 when it is off. */
    public int statusPort() {
        return statusServer == null ? 0 : statusServer.port();
    }

    /** The port of the extension {@code name} ({@code "monitor"}), or 0 when none by that name runs. */
    public int extensionPort(String name) {
        return extensions.stream().filter(e -> e.name().equals(name)).mapToInt(DaemonExtension.Running::port)
                .findFirst().orElse(0);
    }

    /** What an extension may read of this daemon: the status, the outputs and a tap on them; nothing to write. */
    private LiveGraph liveView() {
        return new LiveGraph() {
            @Override
            public ObjectNode status() {
                return Daemon.this.status();
            }

            @Override
            public Map<String, List<String>> inputs() {
                Map<String, List<String>> reads = new LinkedHashMap<>();
                for (MethodConfig m : config.methods()) {
                    reads.put(m.id(), m.inputs().values().stream()
                            .filter(s -> s instanceof Source.MethodOutput)
                            .map(Source::text)
                            .toList());
                }
                return reads;
            }

            @Override
            public List<OutputInfo> outputs() {
                return graph.outputs();
            }

            @Override
            public AutoCloseable watchOutputs(Consumer<Sample> watcher) {
                return graph.watchOutputs(watcher);
            }
        };
    }

    /** The engine's status with the sockets' figures. */
    public ObjectNode status() {
        ObjectNode st = graph.status();
        ArrayNode sockets = st.putArray("sockets");
        servers.values().forEach(s -> sockets.add(s.stats()));
        if (statusServer != null) {
            statusServer.access().putStats(st.putObject("statusEndpoint"));
        }
        st.putObject("blocks")
                .put("bytesInFlight", blockBudget.reserved())
                .put("budgetBytes", blockBudget.limitBytes());
        if (!bridges.isEmpty()) {
            ArrayNode bs = st.putArray("bridges");
            bridges.forEach((id, b) -> bs.add(b.status().put("id", id)));
        }
        return st;
    }

    /** Bytes the control sockets hold now for blocks still arriving (the daemon's own count). */
    public long blockBytesInFlight() {
        return blockBudget.reserved();
    }

    /** Stops the actuators first, then closes the sockets, then stops the graph. Safe to call twice. */
    @Override
    public synchronized void close() {
        if (closed) {
            return;
        }
        closed = true;
        LOG.info("HABLA daemon '{}' stopping: actuators first", config.system());
        graph.stopActuators("the daemon is shutting down");
        bridges.values().forEach(BridgeLink::stop);
        servers.values().forEach(ControlServer::close);
        for (DaemonExtension.Running e : extensions) {
            try {
                e.product().close();
            } catch (Exception ex) {
                LOG.warn("closing the {} failed: {}", e.name(), ex.toString());
            }
        }
        if (statusServer != null) {
            statusServer.close();
        }
        graph.close();
        if (guards != null) {
            guards.close();
        }
        clock.close();
    }
}
